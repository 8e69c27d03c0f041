using System.Buffers;
using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Tests.CMode;

/// <summary>Every C-mode golden vector: frames validate, commands re-encode byte for byte, responses decode.</summary>
public sealed class CModeVectorTests
{
    // Frames in vectors.json that are FCS examples rather than commands a PLC accepts.
    private static readonly string[] NotPlcCommands = { "e5ek_fcs_example", "dws_fcs_hex_letter", "dws_zero_text" };

    private static bool IsCMode(Vector v) => !v.Frames[0].StartsWith("@**", StringComparison.Ordinal) && v.Frames[0].Length > 5 && v.Frames[0].Substring(3, 2) != "FA";

    public static IEnumerable<object[]> GoodCommands => GoldenVectors.Names(v => v.IsCommand && v.FcsOk && IsCMode(v) && !NotPlcCommands.Contains(v.Name));

    public static IEnumerable<object[]> GoodResponses => GoldenVectors.Names(v => v.IsResponse && v.FcsOk && IsCMode(v));

    public static IEnumerable<object[]> GoodFrames => GoldenVectors.Names(v => v.FcsOk && !v.Frames[0].StartsWith("@**", StringComparison.Ordinal));

    public static IEnumerable<object[]> BadFcs => GoldenVectors.Names(v => !v.FcsOk);

    [Theory]
    [MemberData(nameof(GoodFrames))]
    public void Every_frame_of_a_good_vector_validates(string name)
    {
        Vector v = GoldenVectors.Get(name);
        FrameInfo first = FrameParser.ParseFirst(v.FrameBytes(0));
        first.IsFinal.Should().Be(v.Frames.Length == 1);
        for (int i = 1; i < v.Frames.Length; i++)
        {
            FrameInfo next = FrameParser.ParseContinuation(v.FrameBytes(i));
            next.IsFinal.Should().Be(i == v.Frames.Length - 1);
        }
    }

    [Theory]
    [MemberData(nameof(BadFcs))]
    public void A_vector_with_a_wrong_FCS_is_refused(string name)
    {
        Vector v = GoldenVectors.Get(name);
        FluentActions.Invoking(() => FrameParser.ParseFirst(v.FrameBytes(0)))
            .Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.BadFcs);
    }

    [Theory]
    [MemberData(nameof(GoodCommands))]
    public void Every_command_vector_re_encodes_byte_for_byte_from_its_parsed_form(string name)
    {
        Vector v = GoldenVectors.Get(name);
        (int unit, string header, byte[] text) = Reassemble(v);

        CModeCommand command = CModeCommand.Parse(Encoding.ASCII.GetBytes(header), text);

        command.Header.Should().Be(header);
        var writer = new ArrayBufferWriter<byte>();
        int frames = FrameWriter.WriteFrames(writer, command.ToMessage(unit), CModeCommand.PrefixLength + command.FixedTextLength, command.AtomLength);
        frames.Should().Be(v.Frames.Length);
        Encoding.ASCII.GetString(writer.WrittenSpan).Should().Be(string.Concat(v.Frames));
    }

    [Theory]
    [InlineData("dws_fcs_hex_letter", EndCode.FormatError)]
    [InlineData("dws_zero_text", EndCode.FormatError)]
    [InlineData("e5ek_fcs_example", EndCode.UndefinedHeader)]
    public void Frames_that_are_not_valid_commands_get_the_end_code_a_PLC_answers(string name, EndCode expected)
    {
        (_, string header, byte[] text) = Reassemble(GoldenVectors.Get(name));
        FluentActions.Invoking(() => CModeCommand.Parse(Encoding.ASCII.GetBytes(header), text))
            .Should().Throw<CModeCommandRejectedException>().Which.EndCode.Should().Be(expected);
    }

    [Theory]
    [MemberData(nameof(GoodResponses))]
    public void Every_response_vector_decodes(string name)
    {
        Vector v = GoldenVectors.Get(name);
        (int unit, string header, byte[] text) = Reassemble(v);
        switch (name)
        {
            case "c_ts_resp":
                CModeResponse.CheckTestEcho(text, "HELLO-PLC"u8, unit);
                return;
            case "c_ic_resp":
                header.Should().Be("IC");
                text.Should().BeEmpty();
                return;
            case "c_ex_from_plc":
                header.Should().Be("EX");
                return;
            case "roof_sc_resp_0D_misencoded":
                FluentActions.Invoking(() => CModeResponse.GetData(text, header, unit)).Should().Throw<HostLinkEndCodeException>()
                    .Which.EndCode.Should().Be((EndCode)0x0D, "0D is kept as received; it is not the FCS error 13");
                return;
        }

        EndCode code = CModeResponse.ReadEndCode(text);
        if (code != EndCode.NormalCompletion)
        {
            var e = FluentActions.Invoking(() => CModeResponse.GetData(text, header, unit)).Should().Throw<HostLinkEndCodeException>().Which;
            e.EndCode.Should().Be(code);
            e.Header.Should().Be(header);
            e.Unit.Should().Be(unit);
            text.Length.Should().Be(2, "an error response carries no text");
            return;
        }

        ReadOnlySpan<byte> data = CModeResponse.GetData(text, header, unit);
        switch (header)
        {
            case "RR" or "RD" or "RC" or "RH" or "RJ" or "RE" or "RL":
                var words = new ushort[data.Length / 4];
                CModeResponse.ReadWords(data, words);
                Encoding.ASCII.GetString(data).Should().Be(string.Concat(words.Select(w => w.ToString("X4", System.Globalization.CultureInfo.InvariantCulture))));
                break;
            case "RG":
                var flags = new bool[data.Length];
                CModeResponse.ReadFlags(data, flags);
                break;
            case "MS":
                CModeResponse.ReadStatus(data);
                break;
            case "MF":
                CModeResponse.ReadErrors(data).HasErrors.Should().BeFalse();
                break;
            case "MM":
                CModeResponse.ReadModel(data).Name.Should().Be("CS/CJ");
                break;
            default:
                data.IsEmpty.Should().BeTrue($"{header} answers carry no data");
                break;
        }
    }

    [Fact]
    public void Decoded_values_match_the_vectors_meaning()
    {
        Words("c_rd_resp_3w").Should().Equal(0x000A, 0xFFFF, 0x8000);
        Words("c_rr_resp").Should().Equal(0x1234);
        Words("hdr_rr_resp_000A").Should().Equal(0x000A);
        Words("c_rd_multi_response_40w").Should().Equal(Enumerable.Range(0, 40).Select(i => (ushort)(0x1000 + i)));
        Words("c_rd_multi_response_70w").Should().Equal(Enumerable.Range(0, 70).Select(i => (ushort)(0xA000 + i)));

        (int unit, string header, byte[] text) = Reassemble(GoldenVectors.Get("c_rg_resp"));
        var flags = new bool[4];
        CModeResponse.ReadFlags(CModeResponse.GetData(text, header, unit), flags);
        flags.Should().Equal(true, false, true, false);

        Status("c_ms_resp_prog").Mode.Should().Be(PlcMode.Program);
        Status("vb_ms_expected").Mode.Should().Be(PlcMode.Program);
        PlcStatus run = Status("c_ms_resp_run_msg");
        run.Mode.Should().Be(PlcMode.Run);
        run.Message.Should().Be("FAL MESSAGE 01");

        (unit, header, text) = Reassemble(GoldenVectors.Get("c_mm_resp_csj"));
        CModeResponse.ReadModel(CModeResponse.GetData(text, header, unit)).Code.Should().Be(0x30);
    }

    [Fact]
    public void Parsed_commands_carry_the_vectors_meaning()
    {
        Parse<AreaReadCommand>("roof_rd_d100_3").Should().Match<AreaReadCommand>(c => c.Area == CModeArea.Dm && c.Begin == 100 && c.Count == 3);
        Parse<AreaReadCommand>("c_re_cmd").Should().Match<AreaReadCommand>(c => c.Area == CModeArea.Em && c.Bank == 0x0C && c.Begin == 100 && c.Count == 2);
        Parse<AreaReadCommand>("c_rg_cmd").Should().Match<AreaReadCommand>(c => c.Area == CModeArea.TimerCounterStatus && c.Begin == 2048 && c.Count == 4);
        Parse<AreaWriteCommand>("cn_wr_cio102").Words.ToArray().Should().Equal(0x800A, 0x8000);
        Parse<AreaWriteCommand>("c_wj_cmd").Should().Match<AreaWriteCommand>(c => c.Area == CModeArea.Auxiliary && c.Begin == 448);
        Parse<StatusChangeCommand>("roof_sc_monitor").Mode.Should().Be(PlcMode.Monitor);
        Parse<StatusChangeCommand>("ha_sc_run").Mode.Should().Be(PlcMode.Run);
        Parse<StatusChangeCommand>("c_sc_prog").Mode.Should().Be(PlcMode.Program);
        Parse<ErrorReadCommand>("c_mf_cmd").Clear.Should().BeTrue();
        Parse<TestCommand>("java_ts").Text.Should().Be("==HelloPLC");
        Parse<ForceBitCommand>("ha_ks_hr5_06").Should().Match<ForceBitCommand>(c => c.Set && c.Area == ForceArea.Holding && c.Word == 5 && c.Bit == 6);
        Parse<ForceBitCommand>("c_kr_tim").Should().Match<ForceBitCommand>(c => !c.Set && c.Area == ForceArea.Timer && c.Word == 10);
        MultipleForceCommand fk = Parse<MultipleForceCommand>("c_fk_cmd");
        fk.Actions[14].Should().Be(ForceAction.ForcedReset);
        fk.Actions[15].Should().Be(ForceAction.ForcedSet);
        Parse<SimpleCommand>("c_xz_cmd").ExpectsResponse.Should().BeFalse();
    }

    private static T Parse<T>(string name)
        where T : CModeCommand
    {
        (_, string header, byte[] text) = Reassemble(GoldenVectors.Get(name));
        return CModeCommand.Parse(Encoding.ASCII.GetBytes(header), text).Should().BeOfType<T>().Subject;
    }

    private static ushort[] Words(string name)
    {
        (int unit, string header, byte[] text) = Reassemble(GoldenVectors.Get(name));
        ReadOnlySpan<byte> data = CModeResponse.GetData(text, header, unit);
        var words = new ushort[data.Length / 4];
        CModeResponse.ReadWords(data, words);
        return words;
    }

    private static PlcStatus Status(string name)
    {
        (int unit, string header, byte[] text) = Reassemble(GoldenVectors.Get(name));
        return CModeResponse.ReadStatus(CModeResponse.GetData(text, header, unit));
    }

    /// <summary>Validates every frame of a vector and joins their text, as the link does.</summary>
    internal static (int Unit, string Header, byte[] Text) Reassemble(Vector v)
    {
        byte[] f0 = v.FrameBytes(0);
        FrameInfo first = FrameParser.ParseFirst(f0);
        var text = new List<byte>(first.Text(f0).ToArray());
        for (int i = 1; i < v.Frames.Length; i++)
        {
            byte[] f = v.FrameBytes(i);
            text.AddRange(FrameParser.ParseContinuation(f).Text(f).ToArray());
        }

        return (first.Unit, Encoding.ASCII.GetString(first.Header(f0)), text.ToArray());
    }
}
