using System.Text;
using OmronHostLink.Cli.Detection;

namespace OmronHostLink.Cli.Tests;

/// <summary>What <c>detect</c> makes of the bytes that came back after a TS, and what it says when nothing answers.</summary>
public sealed class LineDiagnosisTests
{
    private static readonly byte[] Ts = Encoding.ASCII.GetBytes(GoldenFrames.Frames("java_ts")[0]);

    [Fact]
    public void Replies_are_sorted_into_copies_end_codes_ic_bad_fcs_and_bytes_that_do_not_frame()
    {
        // 7E2 characters read at 8N1: '@' (parity 1) comes back as 0xC0, so nothing frames.
        byte[] garbled = [0xC0, 0x30, 0x30, 0xD4, 0x53, 0x0D];
        string ic = GoldenFrames.Frames("c_ic_resp")[0];
        string damaged = GoldenFrames.Frames("c_ts_resp")[0].Replace("77*", "78*", StringComparison.Ordinal);

        ProbeReply copy = ProbeReply.Of(Ts, Ts);
        ProbeReply echoAndAnswer = ProbeReply.Of(Ts, [.. Ts, .. Ts]);
        ProbeReply noise = ProbeReply.Of(Ts, garbled);
        ProbeReply icAnswer = ProbeReply.Of(Ts, Encoding.ASCII.GetBytes(ic));
        ProbeReply badFcs = ProbeReply.Of(Ts, Encoding.ASCII.GetBytes(damaged));
        ProbeReply endCode = ProbeReply.Of(Ts, Encoding.ASCII.GetBytes("@00TS1345*\r"));

        (copy.Copies, copy.Answered(echo: false), copy.Answered(echo: true)).Should().Be((1, true, false));
        echoAndAnswer.Copies.Should().Be(2);
        echoAndAnswer.Answered(echo: true).Should().BeTrue();
        (noise.Unframed, noise.Copies).Should().Be((6, 0));
        icAnswer.Ic.Should().BeTrue();
        badFcs.BadFcs.Should().Be(1);
        endCode.EndCode.Should().Be("13", "@00TS13 with FCS 45 is TS's error answer with end code 13 (FCS worked out by hand)");
    }

    [Fact]
    public void Bytes_that_do_not_frame_and_frames_with_a_wrong_fcs_are_said_in_words()
    {
        var tries = new List<ProbeTry>
        {
            new(9600, LineFormat.OmronDefault, 0, Ts, ProbeReply.Of(Ts, [0xC0, 0x30, 0x30, 0xD4, 0x0D]), TimeSpan.FromMilliseconds(140), null),
            new(19200, LineFormat.OmronDefault, 0, Ts, ProbeReply.Of(Ts, Encoding.ASCII.GetBytes("@00TSHELLO-PLC78*\r")), TimeSpan.FromMilliseconds(120), null),
        };

        List<string> said = LineDiagnosis.Describe(new LineDetector.Outcome(tries, null, null, TimeSpan.FromMilliseconds(260)), (9600, LineFormat.OmronDefault), [0], settingsFixed: false);

        said.Should().Contain(s => s.StartsWith("Bytes that do not frame came back at 9600 7E2 (at 9600 7E2: \"\\xC000\\xD4\\r\"): something on the line sends at a speed or format other than the one tried", StringComparison.Ordinal));
        said.Should().Contain(s => s.StartsWith("Frames with a wrong FCS came back at 19200 7E2: the speed and format are likely right but the line damages characters", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData(9600, "7E2", 19200, "8N1", "The speed differs (19200 bps, not 9600), and the format differs (8 data bits and no parity, not 7 and even parity).")]
    [InlineData(9600, "7E2", 9600, "7O2", "The format differs (7 data bits and odd parity, not 7 and even parity).")]
    [InlineData(9600, "7E2", 4800, "7E1", "The speed differs (4800 bps, not 9600).")]
    public void A_wrong_speed_or_format_is_named(int givenBaud, string givenFormat, int foundBaud, string foundFormat, string expected)
    {
        LineFormat.TryParse(givenFormat, out LineFormat given).Should().BeTrue();
        LineFormat.TryParse(foundFormat, out LineFormat found).Should().BeTrue();

        LineDiagnosis.Differences((givenBaud, given), (foundBaud, found)).Should().Be(expected);
    }
}
