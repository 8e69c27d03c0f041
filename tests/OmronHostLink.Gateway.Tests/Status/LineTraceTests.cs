using System.Text;
using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Gateway.Status;
using OmronHostLink.Simulator;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// A link's trace: the tap takes the client's frames with their unit and command, leaves the client as it was when
/// removed; the ring keeps the last frames, says how many a slow page missed, and times each answer from the frame
/// before it; each frame is explained as <c>hostlink explain</c> does.
/// </summary>
public sealed class LineTraceTests
{
    [Fact]
    public async Task The_tap_takes_every_frame_of_the_client_with_its_unit_and_command_and_goes_without_a_trace()
    {
        await using InProcessLine line = InProcessLine.Start(plcOptions: new VirtualPlcOptions { Units = [0, 3] });
        line.Plc.WriteWords("D100", [1, 2]);
        var seen = new List<bool>();
        Action<bool, ReadOnlyMemory<byte>> before = (sent, _) => seen.Add(sent);
        line.Client.FrameObserver = before;
        var time = new FakeTimeProvider(new DateTimeOffset(2026, 11, 27, 8, 0, 0, TimeSpan.Zero));
        var trace = new LineTrace(100);

        using (ClientFrameTap.Attach(line.Client, time, trace.Add))
        {
            await line.Client.ReadWordsAsync("D100", 2);
            time.Advance(TimeSpan.FromMilliseconds(5));
            await line.Client.Unit(3).ReadWordsAsync("D100", 1);
        }

        line.Client.FrameObserver.Should().BeSameAs(before, "the tap leaves the client's own observer as it found it");
        seen.Should().NotBeEmpty("the client's own observer was told all along");
        (List<TracedFrame> frames, long lost) = trace.After(0);
        lost.Should().Be(0);
        frames[0].Frame.ToPlc.Should().BeTrue();
        Encoding.ASCII.GetString(frames[0].Frame.Bytes).Should().StartWith("@00RD01000002");
        frames[0].Frame.Unit.Should().Be(0);
        frames[0].Frame.Header.Should().Be("RD");
        frames[0].View.Name.Should().Be("DM AREA READ");
        frames[0].View.Fields.Should().Equal(["area: DM", "begin: 100", "count: 2"]);
        frames[1].Frame.ToPlc.Should().BeFalse();
        frames[1].View.EndCode.Should().Be("00");
        frames[1].View.Fields.Should().Equal(["words: [1, 2]"]);
        frames[1].View.LatencyMs.Should().Be(0, "the fake clock stood still between the command and its answer");
        frames.Should().Contain(f => f.Frame.ToPlc && f.Frame.Unit == 3, "a frame to unit 3 is named after it");

        int count = frames.Count;
        await line.Client.ReadWordsAsync("D100", 2);
        trace.After(0).Frames.Should().HaveCount(count, "without the tap nothing more is taken");
    }

    [Fact]
    public void The_ring_keeps_the_last_frames_and_counts_those_a_page_missed()
    {
        var trace = new LineTrace(10);
        var t0 = new DateTimeOffset(2026, 11, 27, 8, 0, 0, TimeSpan.Zero);
        for (int i = 0; i < 25; i++)
        {
            trace.Add(new LinkFrame(i % 2 == 0, t0.AddMilliseconds(i * 3), Encoding.ASCII.GetBytes(i % 2 == 0 ? "@00RD0000000157*\r" : "@00RD00001B25*\r"), 0, "RD"));
        }

        trace.Last.Should().Be(25);
        (List<TracedFrame> frames, long lost) = trace.After(0);
        frames.Select(f => f.Seq).Should().Equal(Enumerable.Range(16, 10).Select(i => (long)i));
        lost.Should().Be(15);
        trace.After(20).Frames.Select(f => f.Seq).Should().Equal([21L, 22, 23, 24, 25]);
        trace.After(20).Lost.Should().Be(0);
        trace.After(25).Frames.Should().BeEmpty();
        // An answer is timed from the frame out before it: 3 ms apart.
        frames.Where(f => !f.Frame.ToPlc).Should().OnlyContain(f => f.View.LatencyMs == 3);
        frames.Where(f => f.Frame.ToPlc).Should().OnlyContain(f => f.View.LatencyMs == null);
    }

    [Theory]
    [InlineData("\r", true, "CR: send the answer's next frame")]
    [InlineData("\r", false, "CR: the PLC asks for the command's next frame")]
    [InlineData("@00WD0100000153*\r", true, "DM AREA WRITE")]
    [InlineData("@00RD1552*\r", false, "DM AREA READ")]
    public void A_frame_is_explained_as_hostlink_explain_does(string text, bool toPlc, string name)
    {
        var frame = new TracedFrame(1, new LinkFrame(toPlc, DateTimeOffset.UnixEpoch, Encoding.ASCII.GetBytes(text), 0, "RD"), null);

        frame.View.Name.Should().Be(name);
        frame.View.Text.Should().Be(text.Replace("\r", "\\r", StringComparison.Ordinal));
        frame.View.Dir.Should().Be(toPlc ? "out" : "in");
    }

    [Fact]
    public void An_error_answer_carries_its_end_code_and_meaning_and_a_damaged_frame_its_problem()
    {
        var refused = new TracedFrame(1, new LinkFrame(false, DateTimeOffset.UnixEpoch, Encoding.ASCII.GetBytes("@00RD1552*\r"), 0, "RD"), TimeSpan.FromMilliseconds(12));
        refused.View.EndCode.Should().Be("15");
        refused.View.EndCodeMeaning.Should().NotBeNullOrEmpty();
        refused.View.LatencyMs.Should().Be(12);

        var damaged = new TracedFrame(2, new LinkFrame(false, DateTimeOffset.UnixEpoch, Encoding.ASCII.GetBytes("@00RD00001B26*\r"), 0, "RD"), null);
        damaged.View.Problems.Should().ContainSingle().Which.Should().Contain("FCS");
    }
}
