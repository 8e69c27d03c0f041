using System.Globalization;
using System.Text;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// A Serial Communications Unit's Host Link-compatible device mode (W336 4-6-2, printed p141; mode table printed p301;
/// W342 2-4-1, printed p15): the simulator frames answers as each mode does, and the client reads both forms right —
/// 30/31 words a frame (mode A, a CPU's own port) and 29/30 (mode C), MS with and without the 16 message characters —
/// and, told the mode, refuses an answer framed as another mode frames it. The frame sizes here are the manual's.
/// </summary>
public sealed class CompatibleModeTests
{
    [Theory]
    // words, first-frame words, later-frame words: W336 p301 (mode A 30/31, mode C 29/30).
    [InlineData(HostLinkCompatibleMode.ModeA, 100, new[] { 30, 31, 31, 8 })]
    [InlineData(HostLinkCompatibleMode.ModeB, 100, new[] { 30, 31, 31, 8 })]
    [InlineData(HostLinkCompatibleMode.ModeC, 100, new[] { 29, 30, 30, 11 })]
    [InlineData(HostLinkCompatibleMode.ModeC, 30, new[] { 29, 1 })]
    [InlineData(HostLinkCompatibleMode.ModeA, 30, new[] { 30 })]
    public async Task The_simulator_frames_a_DM_read_as_the_mode_does(HostLinkCompatibleMode mode, int count, int[] wordsPerFrame)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = mode });
        ushort[] values = Enumerable.Range(1, count).Select(i => (ushort)(0x1000 + i)).ToArray();
        plc.WriteWords(PlcArea.Dm, 0, values);
        await using RawHost raw = RawHost.Start(plc);

        await ExpectFramesAsync(raw, "RD", count, Hex(values), [.. wordsPerFrame.Select(w => w * 4)]);
    }

    [Theory]
    // RG completion flags: mode A 121/125, mode C 89/89 (W336 p301).
    [InlineData(HostLinkCompatibleMode.ModeA, 300, new[] { 121, 125, 54 })]
    [InlineData(HostLinkCompatibleMode.ModeC, 200, new[] { 89, 89, 22 })]
    public async Task The_simulator_frames_an_RG_read_as_the_mode_does(HostLinkCompatibleMode mode, int count, int[] flagsPerFrame)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = mode });
        for (int t = 0; t < count; t += 3)
        {
            plc.SetFlag(PlcArea.Timer, t, true);
        }

        string flags = string.Concat(Enumerable.Range(0, count).Select(t => t % 3 == 0 ? '1' : '0'));
        await using RawHost raw = RawHost.Start(plc);

        await ExpectFramesAsync(raw, "RG", count, flags, flagsPerFrame);
    }

    [Theory]
    [InlineData(null, HostLinkCompatibleMode.ModeC)]
    [InlineData(HostLinkCompatibleMode.ModeC, HostLinkCompatibleMode.ModeC)]
    [InlineData(null, HostLinkCompatibleMode.ModeA)]
    [InlineData(HostLinkCompatibleMode.ModeA, HostLinkCompatibleMode.ModeA)]
    [InlineData(HostLinkCompatibleMode.ModeB, HostLinkCompatibleMode.ModeB)]
    [InlineData(HostLinkCompatibleMode.ModeA, null)]
    public async Task The_client_reads_words_and_flags_right_in_every_framing_it_accepts(HostLinkCompatibleMode? client, HostLinkCompatibleMode? unit)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = unit });
        ushort[] values = Enumerable.Range(0, 200).Select(i => (ushort)(i * 7)).ToArray();
        plc.WriteWords(PlcArea.Dm, 100, values);
        plc.SetFlag(PlcArea.Timer, 88, true);
        plc.SetFlag(PlcArea.Timer, 89, true);
        plc.SetFlag(PlcArea.Timer, 250, true);
        await using var line = EmulatedLine.Start(plc, null, client);

        (await line.Client.ReadWordsAsync("D100", 200)).Should().Equal(values);
        bool[] read = await line.Client.ReadBitsAsync(PlcAddress.Parse("T0"), 300);

        read.Select((on, t) => (on, t)).Where(x => x.on).Select(x => x.t).Should().Equal(88, 89, 250);
    }

    [Fact]
    public async Task Sixty_words_take_three_frames_in_mode_C_and_two_in_mode_A()
    {
        foreach ((HostLinkCompatibleMode mode, int frames) in new[] { (HostLinkCompatibleMode.ModeC, 3), (HostLinkCompatibleMode.ModeA, 2) })
        {
            var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = mode });
            await using var line = EmulatedLine.Start(plc, null, mode);

            await line.Client.ReadWordsAsync("D0", 60);

            // The command, then a bare CR asking for each later answer frame.
            line.SentFrames.Should().HaveCount(frames, $"{mode}: 29/30 or 30/31 words a frame");
            line.SentFrames.Skip(1).Should().OnlyContain(f => f == "\r");
        }
    }

    [Theory]
    [InlineData(HostLinkCompatibleMode.ModeA, HostLinkCompatibleMode.ModeC, "first frame carried 29 words; a Serial Communications Unit in Host Link-compatible mode A (CS/CJ/C) sends 30.")]
    [InlineData(HostLinkCompatibleMode.ModeC, HostLinkCompatibleMode.ModeA, "first frame carried 30 words; a Serial Communications Unit in Host Link-compatible mode C (C200H) sends 29.")]
    [InlineData(HostLinkCompatibleMode.ModeC, null, "first frame carried 30 words; a Serial Communications Unit in Host Link-compatible mode C (C200H) sends 29.")]
    public async Task Told_the_mode_the_client_refuses_an_answer_framed_as_another_mode(HostLinkCompatibleMode client, HostLinkCompatibleMode? unit, string message)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = unit });
        await using var line = EmulatedLine.Start(plc, null, client);

        var e = await FluentActions.Awaiting(() => line.Client.ReadWordsAsync("D0", 100)).Should().ThrowAsync<HostLinkFrameException>();

        e.Which.Error.Should().Be(FrameError.WrongLength);
        e.Which.Message.Should().Contain("The RD answer's " + message);

        // The link is left clean: a read that fits one frame in both framings goes through.
        (await line.Client.ReadWordsAsync("D0", 2)).Should().HaveCount(2);
    }

    [Theory]
    [InlineData(HostLinkCompatibleMode.ModeA, false)]
    [InlineData(HostLinkCompatibleMode.ModeB, true)]
    [InlineData(HostLinkCompatibleMode.ModeC, false)]
    [InlineData(null, false)]
    public async Task MS_sends_the_message_characters_as_spaces_in_mode_B_and_leaves_them_out_otherwise(HostLinkCompatibleMode? mode, bool spaces)
    {
        // W336 p301 note 1: "fixed length" modes add spaces for the FAL/FALS message, "variable length" ones add none.
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = mode });
        await using RawHost raw = RawHost.Start(plc);

        string answer = await raw.TransactAsync(RawHost.Command("@00MS"));

        string status = answer.Substring(7, 4);
        answer.Should().Be(RawHost.Command("@00MS00" + status + (spaces ? new string(' ', 16) : string.Empty)));
    }

    [Theory]
    [InlineData(HostLinkCompatibleMode.ModeA, null)]
    [InlineData(HostLinkCompatibleMode.ModeB, null)]
    [InlineData(HostLinkCompatibleMode.ModeA, "MOTOR OVERLOAD")]
    [InlineData(HostLinkCompatibleMode.ModeB, "MOTOR OVERLOAD")]
    [InlineData(HostLinkCompatibleMode.ModeB, "0123456789ABCDEF")]
    public async Task The_client_reads_MS_the_same_in_both_forms(HostLinkCompatibleMode mode, string? fal)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = mode, InitialMode = PlcMode.Monitor });
        plc.FalMessage = fal;
        await using var line = EmulatedLine.Start(plc, null, mode);

        PlcStatus status = await line.Client.ReadStatusAsync();

        status.Mode.Should().Be(PlcMode.Monitor);
        status.Message.Should().Be(fal, "16 spaces are no message, as no characters are");
    }

    [Fact]
    public void Mode_D_is_not_emulated_because_the_manual_pages_found_do_not_give_all_of_it()
    {
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { HostLinkCompatibleMode = HostLinkCompatibleMode.ModeD }))
            .Should().Throw<ArgumentException>().WithMessage("HostLinkCompatibleMode ModeD is not emulated*Use ModeA, ModeB or ModeC.*");
    }

    [Theory]
    [InlineData("C", HostLinkCompatibleMode.ModeC)]
    [InlineData("modeb", HostLinkCompatibleMode.ModeB)]
    [InlineData("ModeD", HostLinkCompatibleMode.ModeD)]
    public void The_mode_is_a_client_setting(string value, HostLinkCompatibleMode mode)
    {
        var settings = new HostLinkClientSettings();
        settings.Read([new("Tcp:Host", "127.0.0.1"), new("Tcp:Port", "9600"), new("HostLinkCompatibleMode", value)]);

        settings.Validate().Should().BeEmpty();
        settings.ToClientOptions().HostLinkCompatibleMode.Should().Be(mode);
        new HostLinkClientSettings().ToClientOptions().HostLinkCompatibleMode.Should().BeNull("unset, any framing is accepted");
    }

    [Fact]
    public void An_unknown_mode_is_refused_naming_the_key_and_the_choices()
    {
        var settings = new HostLinkClientSettings();
        settings.Read([new("Tcp:Host", "127.0.0.1"), new("Tcp:Port", "9600"), new("HostLinkCompatibleMode", "E")]);

        settings.Validate().Should().ContainSingle(p => p.Key == "HostLinkCompatibleMode")
            .Which.Message.Should().Contain("'E' is not one of ModeA, ModeB, ModeC, ModeD, A, B, C, D");
        FluentActions.Invoking(new HostLinkClientOptions { HostLinkCompatibleMode = (HostLinkCompatibleMode)7 }.Validate)
            .Should().Throw<ArgumentOutOfRangeException>().WithMessage("HostLinkCompatibleMode 7 is not ModeA, ModeB, ModeC or ModeD.*");
    }

    // Sends a read of count entries from 0 and checks each answer frame: the data characters it carries, the first frame
    // after "@00", the header and end code 00, a bare CR between frames, "*" CR after the last.
    private static async Task ExpectFramesAsync(RawHost raw, string header, int count, string data, int[] charactersPerFrame)
    {
        await raw.SendAsync(RawHost.Command("@00" + header + "0000" + count.ToString("D4", CultureInfo.InvariantCulture)));

        int at = 0;
        for (int i = 0; i < charactersPerFrame.Length; i++)
        {
            if (i > 0)
            {
                await raw.SendAsync("\r");
            }

            string text = (i == 0 ? "@00" + header + "00" : string.Empty) + data.Substring(at, charactersPerFrame[i]);
            at += charactersPerFrame[i];
            bool last = i == charactersPerFrame.Length - 1;
            (await raw.ReadFrameAsync()).Should().Be(last ? RawHost.Command(text) : RawHost.Delimited(text), $"frame {i + 1} carries {charactersPerFrame[i]} data characters");
        }
    }

    private static string Hex(ReadOnlySpan<ushort> words)
    {
        var text = new StringBuilder();
        foreach (ushort w in words)
        {
            text.Append(w.ToString("X4", CultureInfo.InvariantCulture));
        }

        return text.ToString();
    }
}
