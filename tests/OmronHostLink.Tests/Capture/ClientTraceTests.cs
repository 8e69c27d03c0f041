using System.Text;
using OmronHostLink.Capture;

namespace OmronHostLink.Tests.Capture;

/// <summary>The client's trace option: every frame of the link, with direction and time, in a capture file.</summary>
public sealed class ClientTraceTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("ohl-trace-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public async Task Every_frame_sent_and_received_is_written_with_its_direction()
    {
        string path = Path.Combine(_dir, "trace.pcap");
        await using (InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { TraceFile = path }))
        {
            line.Plc.WriteWords("D100", [0x000A, 0xFFFF, 0x8000]);
            (await line.Client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);
            await line.Client.ReadWordsAsync("D0", 40);
        }

        IReadOnlyList<CapturedFrame> frames = CaptureReader.Read(path);

        // The RD of 3 words and its answer (golden frame c_rd_resp_3w is an answer of D0-D2 of the same shape), then
        // the RD of 40 words: its answer spans two frames, with the host's bare CR between them.
        frames.Select(f => f.Direction).Should().Equal(
            LineDirection.ToPlc, LineDirection.FromPlc,
            LineDirection.ToPlc, LineDirection.FromPlc, LineDirection.ToPlc, LineDirection.FromPlc);
        Encoding.ASCII.GetString(frames[0].Bytes).Should().Be("@00RD0100000354*\r", "golden vector roof_rd_d100_3");
        Encoding.ASCII.GetString(frames[1].Bytes).Should().Be("@00RD00000AFFFF80002F*\r", "the answer carries the words of golden vector c_rd_resp_3w");
        frames[4].Bytes.Should().Equal((byte)'\r');
        frames.Zip(frames.Skip(1)).Should().OnlyContain(p => p.First.Time <= p.Second.Time);
    }

    [Fact]
    public async Task Json_lines_are_written_for_a_jsonl_name()
    {
        string path = Path.Combine(_dir, "trace.jsonl");
        await using (InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { TraceFile = path }))
        {
            await line.Client.ReadStatusAsync();
        }

        string[] lines = File.ReadAllLines(path);

        lines.Should().HaveCount(2);
        lines[0].Should().Contain("\"direction\":\"toPlc\"").And.Contain("\"header\":\"MS\"");
        lines[1].Should().Contain("\"direction\":\"fromPlc\"");
    }

    [Fact]
    public void A_trace_file_that_cannot_be_created_is_refused_when_the_client_is()
    {
        string path = Path.Combine(_dir, "no-such-folder", "trace.pcap");

        FluentActions.Invoking(() => HostLinkClient.ForStream(new MemoryStream(), new HostLinkClientOptions { TraceFile = path }))
            .Should().Throw<ArgumentException>().WithMessage($"TraceFile '{path}' cannot be created:*").Which.ParamName.Should().Be("TraceFile");
    }

    [Fact]
    public async Task The_frame_observer_and_the_trace_are_told_of_the_same_frames()
    {
        string path = Path.Combine(_dir, "both.pcap");
        var observed = new List<(bool Sent, string Frame)>();
        await using (InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { TraceFile = path }))
        {
            Action<bool, ReadOnlyMemory<byte>>? counting = line.Client.FrameObserver;
            line.Client.FrameObserver = (sent, frame) =>
            {
                counting?.Invoke(sent, frame);
                observed.Add((sent, Encoding.ASCII.GetString(frame.Span)));
            };
            await line.Client.ReadModelAsync();
        }

        IReadOnlyList<CapturedFrame> frames = CaptureReader.Read(path);

        frames.Select(f => (f.Direction == LineDirection.ToPlc, Encoding.ASCII.GetString(f.Bytes))).Should().Equal(observed);
        observed[0].Frame.Should().Be("@00MM40*\r", "golden vector c_mm");
        observed[1].Frame.Should().Be("@00MM003043*\r", "golden vector c_mm_resp_csj");
    }
}
