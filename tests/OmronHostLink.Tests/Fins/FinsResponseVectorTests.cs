using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

public class FinsResponseVectorTests
{
    public static IEnumerable<object[]> GoodFinsResponses => FinsVectors.GoodFinsResponses;

    public static IEnumerable<object[]> BadFcs => FinsVectors.BadFcs;

    /// <summary>The command header a response answers: SID echoed, addresses swapped back.</summary>
    private static FinsHeader CommandHeaderOf(FinsHeader response)
        => response.IsNetwork
            ? FinsHeader.Network(response.Sna, response.Sa1, response.Sa2, response.Dna, response.Da1, response.Da2, response.Sid, response.Gct)
            : FinsHeader.Direct(response.Sid);

    private static FinsResponse Decode(string name, FinsHeader commandHeader, ushort commandCode)
        => FinsResponse.ParseFrame(GoldenVectors.Get(name).FrameBytes(), 0, commandHeader, commandCode);

    [Theory]
    [MemberData(nameof(GoodFinsResponses))]
    public void Response_vector_decodes_and_the_writer_reproduces_it(string name)
    {
        byte[] frame = GoldenVectors.Get(name).FrameBytes();
        FrameInfo info = FrameParser.ParseFirst(frame);
        FinsResponse loose = FinsResponse.Parse(info.Text(frame), info.Unit);

        FinsHeader commandHeader = CommandHeaderOf(loose.Header);
        FinsResponse checkedResponse = FinsResponse.ParseFrame(frame, info.Unit, commandHeader, loose.CommandCode);
        checkedResponse.EndCode.Should().Be(loose.EndCode);
        checkedResponse.Data.ToArray().Should().Equal(loose.Data.ToArray());
        checkedResponse.Header.Should().Be(commandHeader.ToResponseHeader());

        byte[] written = FinsMessage.EncodeResponseFrame(info.Unit, commandHeader, loose.CommandCode, loose.EndCode, loose.Data.Span);
        FrameText.Printable(written).Should().Be(FrameText.Printable(frame));
    }

    [Theory]
    [MemberData(nameof(BadFcs))]
    public void Vector_with_a_wrong_FCS_is_rejected(string name)
    {
        Vector vector = GoldenVectors.Get(name);
        byte[] frame = vector.FrameBytes();

        var parse = () => FrameParser.ParseFirst(frame);
        parse.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.BadFcs);

        if (vector.IsResponse)
        {
            var decode = () => FinsResponse.ParseFrame(frame, 0, FinsHeader.Direct(), 0x0101);
            decode.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.BadFcs);
        }
        else
        {
            var decode = () => FinsMessage.ParseCommandFrame(frame);
            decode.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.BadFcs);
        }
    }

    [Fact]
    public void Read_response_D100_D101()
    {
        FinsResponse r = Decode("f_0101_rsp", FinsHeader.Direct(), 0x0101);
        r.Unit.Should().Be(0);
        r.IsSuccess.Should().BeTrue();
        r.EndCode.Raw.Should().Be(0);
        r.Header.Icf.Should().Be(0x40);
        FinsWords.Read(r.Data.Span, 2).Should().Equal(0x1234, 0xABCD);
        r.ThrowIfError();
    }

    [Fact]
    public void Read_response_H13()
        => FinsWords.Read(Decode("cs_fins_read_h13_resp", FinsHeader.Direct(), 0x0101).Data.Span, 1).Should().Equal(0);

    [Fact]
    public void Read_response_must_hold_exactly_count_words()
    {
        FinsResponse r = Decode("f_0101_rsp", FinsHeader.Direct(), 0x0101);
        var tooFew = () => FinsWords.Read(r.Data.Span, 3);
        tooFew.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
        var tooMany = () => FinsWords.Read(r.Data.Span, 1);
        tooMany.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public void Published_bit_read_payload_decodes_although_its_commented_FCS_is_wrong()
    {
        // java_fins_read_cio_bits_resp carries a wrong FCS (only its frame check is at fault): decode its text.
        byte[] frame = GoldenVectors.Get("java_fins_read_cio_bits_resp").FrameBytes();
        ReadOnlySpan<byte> text = frame.AsSpan(5, frame.Length - 5 - 4);
        FinsResponse r = FinsResponse.Parse(text, 0, FinsHeader.Direct(), 0x0101);
        FinsBits.Read(r.Data.Span, 5).Should().Equal(false, true, false, true, true);
    }

    [Fact]
    public void Write_response_normal()
    {
        FinsResponse r = Decode("hsl_fins_write_resp", FinsHeader.Direct(), 0x0102);
        r.IsSuccess.Should().BeTrue();
        r.Data.Length.Should().Be(0);
        r.ThrowIfError();
    }

    [Fact]
    public void Write_response_2101_read_only()
    {
        FinsResponse r = Decode("f_0102_rsp_2101", FinsHeader.Direct(), 0x0102);
        r.IsSuccess.Should().BeFalse();
        r.EndCode.Code.Should().Be(0x2101);
        var act = () => r.ThrowIfError();
        FinsEndCodeException e = act.Should().Throw<FinsEndCodeException>().Which;
        e.EndCode.Code.Should().Be(0x2101);
        e.Command.Should().Be(0x0102);
        e.Unit.Should().Be(0);
        e.EndCode.Meaning.Should().Contain("read-only");
    }

    [Fact]
    public void Multiple_read_response_checks_area_echo()
    {
        var command = (MultipleMemoryAreaReadCommand)FinsMessage.ParseCommandFrame(GoldenVectors.Get("f_0104_cmd").FrameBytes()).ToCommand();
        FinsResponse r = Decode("f_0104_rsp", FinsHeader.Direct(), 0x0104);
        FinsMultipleReadValue[] values = FinsMultipleReadValue.ReadAll(r.Data.Span, command);
        values.Should().HaveCount(3);
        values[0].AreaCode.Should().Be(0x82);
        values[0].Word.Should().Be(0x1111);
        values[1].AreaCode.Should().Be(0xB0);
        values[1].Word.Should().Be(0x2222);
        values[2].AreaCode.Should().Be(0x30);
        values[2].Bit.Should().BeTrue();

        var swapped = new MultipleMemoryAreaReadCommand(new[] { command.Items[1], command.Items[0], command.Items[2] });
        var act = () => FinsMultipleReadValue.ReadAll(r.Data.Span, swapped);
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongHeader);
    }

    [Fact]
    public void Stop_response_normal()
        => Decode("f_0402_rsp", FinsHeader.Direct(), 0x0402).IsSuccess.Should().BeTrue();

    [Fact]
    public void Cpu_status_response()
    {
        FinsResponse r = Decode("f_0601_rsp", FinsHeader.Direct(), 0x0601);
        FinsCpuStatus status = FinsCpuStatus.Read(r.Data.Span);
        status.Status.Should().Be(0x01);
        status.IsRunning.Should().BeTrue();

        // The vector's meaning says "mode 02 (RUN)"; by the 0401/0601 mode table 02 is MONITOR (see report).
        status.Mode.Should().Be(FinsCpuMode.Monitor);
        status.FatalErrors.Should().Be(0);
        status.NonFatalErrors.Should().Be(0);
        status.Messages.Should().Be(0);
        status.FalNumber.Should().Be(0);
        status.ErrorMessage.Should().BeEmpty();
    }

    [Fact]
    public void Clock_response()
    {
        FinsResponse r = Decode("f_0701_rsp", FinsHeader.Direct(), 0x0701);
        FinsClock clock = FinsClock.Read(r.Data.Span);
        clock.Time.Should().Be(new DateTime(2024, 5, 17, 13, 45, 30));
        clock.DayOfWeek.Should().Be(DayOfWeek.Friday);
    }

    [Fact]
    public void Response_code_0040_is_success_with_the_non_fatal_flag_visible()
    {
        FinsResponse r = Decode("f_rsp_0040_nonfatal", FinsHeader.Direct(), 0x0101);
        r.EndCode.Raw.Should().Be(0x0040);
        r.EndCode.Code.Should().Be(0x0000);
        r.EndCode.NonFatalCpuError.Should().BeTrue();
        r.EndCode.FatalCpuError.Should().BeFalse();
        r.IsSuccess.Should().BeTrue();
        r.ThrowIfError();
        FinsWords.Read(r.Data.Span, 1).Should().Equal(0);
    }

    [Fact]
    public void Response_code_1103_address_range()
    {
        FinsResponse r = Decode("f_rsp_1103", FinsHeader.Direct(), 0x0101);
        r.Data.Length.Should().Be(0);
        var act = () => r.ThrowIfError();
        act.Should().Throw<FinsEndCodeException>().Which.EndCode.Meaning.Should().Be("Address range error");
    }

    [Fact]
    public void Response_code_8401_relay_error()
    {
        FinsResponse r = Decode("f_rsp_8401_relay", FinsHeader.Direct(), 0x0101);
        r.EndCode.NetworkRelayError.Should().BeTrue();
        r.EndCode.Code.Should().Be(0x0401);
        r.EndCode.MainCode.Should().Be(0x04);
        r.EndCode.SubCode.Should().Be(0x01);
        var act = () => r.ThrowIfError();
        act.Should().Throw<FinsEndCodeException>().Which.EndCode.Raw.Should().Be(0x8401);
    }

    [Fact]
    public void Network_response_answers_the_network_command()
    {
        FinsCommandMessage command = FinsMessage.ParseCommandFrame(GoldenVectors.Get("f_network_cmd").FrameBytes());
        FinsResponse r = Decode("f_network_rsp", command.Header, command.CommandCode);
        r.Header.Icf.Should().Be(0xC0);
        r.Header.Sid.Should().Be(command.Header.Sid);
        r.Header.Dna.Should().Be(command.Header.Sna);
        r.Header.Da1.Should().Be(command.Header.Sa1);
        r.Header.Da2.Should().Be(command.Header.Sa2);
        r.Header.Sna.Should().Be(command.Header.Dna);
        r.Header.Sa1.Should().Be(command.Header.Da1);
        r.Header.Sa2.Should().Be(command.Header.Da2);
        r.Header.Gct.Should().Be(2);
        FinsWords.Read(r.Data.Span, 1).Should().Equal(0xABCD);

        // The writer, given the command's header, produces the vector.
        FinsMessage.EncodeResponseFrame(0, command.Header, 0x0101, r.EndCode, r.Data.Span)
            .Should().Equal(GoldenVectors.Get("f_network_rsp").FrameBytes());
    }

    [Fact]
    public void Network_response_to_a_direct_command_is_refused()
    {
        var act = () => Decode("f_network_rsp", FinsHeader.Direct(sid: 1), 0x0101);
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongHeader);
    }

    [Fact]
    public void Host_Link_level_error_14_has_no_FINS_part()
    {
        var act = () => Decode("f_hl_err_14", FinsHeader.Direct(), 0x0101);
        HostLinkEndCodeException e = act.Should().Throw<HostLinkEndCodeException>().Which;
        e.EndCode.Should().Be(EndCode.FormatError);
        e.Header.Should().Be("FA");
        e.Unit.Should().Be(0);
    }

    [Fact]
    public void Host_Link_level_error_writer_reproduces_the_vector()
        => Encoding.ASCII.GetString(FinsMessage.EncodeHostLinkErrorFrame(0, EndCode.FormatError)).Should().Be(GoldenVectors.Get("f_hl_err_14").Frames[0]);

    [Fact]
    public void Response_with_another_SID_or_command_is_refused()
    {
        var sid = () => Decode("f_0101_rsp", FinsHeader.Direct(sid: 9), 0x0101);
        sid.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongHeader);
        var code = () => Decode("f_0101_rsp", FinsHeader.Direct(), 0x0102);
        code.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongHeader);
        var unit = () => FinsResponse.ParseFrame(GoldenVectors.Get("f_0101_rsp").FrameBytes(), 3, FinsHeader.Direct(), 0x0101);
        unit.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongUnit);
    }
}
