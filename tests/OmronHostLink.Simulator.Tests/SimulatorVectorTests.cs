using System.Globalization;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator;

namespace OmronHostLink.Simulator.Tests;

/// <summary>The simulator answers the golden command vectors as a CS/CJ PLC does.</summary>
public class SimulatorVectorTests
{
    /// <summary>Vectors that are not valid PLC commands, with what the simulator answers (null = silence).</summary>
    private static readonly Dictionary<string, string?> Special = new()
    {
        ["manual_fcs_example_RR"] = "13", // FCS does not verify
        ["e5ek_fcs_example"] = "IC",      // header "10" is no C-mode command
        ["dws_fcs_hex_letter"] = "14",
        ["dws_zero_text"] = "14",
        ["c_xz_cmd"] = null,
        ["c_init_cmd"] = null,
    };

    public static TheoryData<string> SingleFrameCModeCommands()
    {
        var data = new TheoryData<string>();
        foreach (SimVector v in SimVectors.Vectors)
        {
            if (v.Direction == "command" && v.Frames.Count == 1 && !v.Frames[0].StartsWith("@00FA", StringComparison.Ordinal) && !(v.Frames[0].Length > 5 && v.Frames[0][3..5] == "FA"))
            {
                data.Add(v.Name);
            }
        }

        return data;
    }

    [Fact]
    public void The_vector_file_is_there_and_has_command_vectors()
    {
        File.Exists(SimVectors.Path).Should().BeTrue();
        ((IEnumerable<object[]>)SingleFrameCModeCommands()).Count().Should().BeGreaterThan(40);
    }

    [Theory]
    [MemberData(nameof(SingleFrameCModeCommands))]
    public async Task Every_single_frame_command_vector_gets_a_well_formed_answer(string name)
    {
        SimVector v = SimVectors.Get(name);
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Units = Enumerable.Range(0, 32).ToArray() });
        string frame = v.Frames[0];
        await host.SendAsync(frame);

        if (Special.TryGetValue(name, out string? expected) && expected is null)
        {
            await host.ExpectSilenceAsync();
            return;
        }

        Response r = Response.Parse(await host.ReadFrameAsync());
        int unit = int.Parse(frame.Substring(1, 2), CultureInfo.InvariantCulture);
        string header = frame.Substring(3, 2);
        r.Unit.Should().Be(unit);
        if (expected == "IC")
        {
            r.Header.Should().Be("IC");
            r.Text.Should().BeEmpty();
            return;
        }

        r.Header.Should().Be(header);
        if (header == "TS")
        {
            r.Text.Should().Be(frame[5..^4], "TS echoes its text without an end code");
            return;
        }

        r.EndCode.Should().Be(expected ?? "00", v.Notes);
        if (expected is not null)
        {
            r.Data.Should().BeEmpty("error answers carry no text");
        }
        else if (header[0] == 'R' && header != "RG")
        {
            int count = int.Parse(frame.Substring(frame.Length - 8, 4), CultureInfo.InvariantCulture);
            r.Data.Length.Should().Be(count * 4);
        }
        else if (header == "RG")
        {
            r.Data.Length.Should().Be(int.Parse(frame.Substring(frame.Length - 8, 4), CultureInfo.InvariantCulture));
        }
    }

    [Theory]
    [InlineData("c_rd_multi_response_40w", 40)]
    [InlineData("c_rd_multi_response_70w", 70)]
    public async Task Multi_frame_read_responses_match_the_vectors_byte_for_byte(string name, int words)
    {
        SimVector v = SimVectors.Get(name);
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Dm, 0, WordsOf(v.Frames, words));
        await using RawHost host = RawHost.Start(plc);

        await host.SendAsync(RawHost.Command($"@00RD0000{words:D4}"));
        for (int i = 0; i < v.Frames.Count; i++)
        {
            if (i > 0)
            {
                await host.SendAsync("\r");
            }

            (await host.ReadFrameAsync()).Should().Be(v.Frames[i], $"frame {i + 1} of {v.Frames.Count}");
        }

        await host.ExpectSilenceAsync(TimeSpan.FromMilliseconds(100));
        (await host.TransactAsync(RawHost.Command("@00MS"))).Should().StartWith("@00MS00", "the exchange is over");
    }

    [Fact]
    public async Task The_40_word_command_from_the_vector_notes_gives_the_vector()
    {
        SimVector v = SimVectors.Get("c_rd_multi_response_40w");
        v.Notes.Should().Contain("@00RD0000004052*");
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Dm, 0, WordsOf(v.Frames, 40));
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync("@00RD0000004052*\r")).Should().Be(v.Frames[0]);
        (await host.TransactAsync("\r")).Should().Be(v.Frames[1]);
    }

    [Theory]
    [InlineData("c_wd_multi_command_50w", PlcArea.Dm, 1000, 50, "@00WD0053*\r")]
    [InlineData("c_wr_multi_command_80w", PlcArea.Cio, 0, 80, "@00WR0045*\r")]
    public async Task Multi_frame_write_commands_are_acknowledged_frame_by_frame(string name, PlcArea area, int begin, int words, string final)
    {
        SimVector v = SimVectors.Get(name);
        await using RawHost host = RawHost.Start();
        for (int i = 0; i < v.Frames.Count - 1; i++)
        {
            (await host.TransactAsync(v.Frames[i])).Should().Be("\r", $"the PLC asks for frame {i + 2} with a bare CR");
        }

        (await host.TransactAsync(v.Frames[^1])).Should().Be(final);
        ushort[] expected = WriteData(v.Frames, area == PlcArea.Dm ? "@00WD1000".Length : "@00WR0000".Length);
        expected.Should().HaveCount(words);
        host.Plc.ReadWords(area, begin, words).Should().Equal(expected);
    }

    [Fact]
    public void The_final_WR_acknowledgement_used_above_has_a_valid_FCS()
    {
        Response.Parse("@00WR0045*\r").EndCode.Should().Be("00");
    }

    /// <summary>The words of a multi-frame read response.</summary>
    private static ushort[] WordsOf(IReadOnlyList<string> frames, int count)
    {
        var hex = string.Concat(frames.Select((f, i) => Text(f, i == 0 ? 7 : 0)));
        hex.Length.Should().Be(count * 4);
        return Enumerable.Range(0, count).Select(i => ushort.Parse(hex.AsSpan(i * 4, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture)).ToArray();
    }

    /// <summary>The data words of a multi-frame write command.</summary>
    private static ushort[] WriteData(IReadOnlyList<string> frames, int skip)
    {
        var hex = string.Concat(frames.Select((f, i) => Text(f, i == 0 ? skip : 0)));
        return Enumerable.Range(0, hex.Length / 4).Select(i => ushort.Parse(hex.AsSpan(i * 4, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture)).ToArray();
    }

    /// <summary>The text of a frame after <paramref name="skip"/> characters, without FCS and ending.</summary>
    private static string Text(string frame, int skip)
    {
        int end = frame.EndsWith("*\r", StringComparison.Ordinal) ? frame.Length - 4 : frame.Length - 3;
        return frame[skip..end];
    }

    [Fact]
    public void Fcs_helper_agrees_with_the_package()
    {
        RawHost.Command("@00RD00000010").Should().Be("@00RD0000001057*\r");
        Fcs.Compute("@00RD00000010"u8).Should().Be(0x57);
    }
}
