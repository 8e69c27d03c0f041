using System.Diagnostics;
using System.Text;
using BenchmarkDotNet.Attributes;
using OmronHostLink.Capture;
using OmronHostLink.Cli.Commands;
using OmronHostLink.Cli.LineMonitoring;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// What <c>hostlink monitor-line</c> does with the bytes of a busy line, per frame: cut it out of small chunks (a serial
/// read at 115200 bps returns about a millisecond of bytes), pair it, write it to a pcap, and format each exchange's line
/// as the console prints it. The line is golden frames: a one-frame RD and its answer, a 40-word RD answered in two
/// frames, a 50-word WD sent in two, a TS; 1,000 rounds of them, 11,000 frames.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class LineMonitorBenchmarks
{
    private const int Rounds = 1000;
    private TapChunk[] _chunks = [];
    private int _frames;
    private string _capture = "";

    [Params(false, true)]
    public bool Capture { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        string[] rd40 = GoldenFrames.Rd40Frames;
        string[] wd50 = GoldenFrames.Wd50Frames;
        string[] round =
        [
            "@00RD0000001057*\r", "@00RD00000AFFFF80002F*\r",
            "@00RD0000004052*\r", rd40[0], "\r", rd40[1],
            wd50[0], "\r", wd50[1], "@00WD0053*\r",
            "@00TS==HelloPLC5A*\r", "@00TS==HelloPLC5A*\r",
        ];
        byte[] line = Encoding.ASCII.GetBytes(string.Concat(Enumerable.Repeat(string.Concat(round), Rounds)));
        _frames = round.Length * Rounds;
        var chunks = new List<TapChunk>();
        long ticks = Stopwatch.GetTimestamp();
        for (int at = 0; at < line.Length; at += 12)
        {
            chunks.Add(new TapChunk(0, line.AsSpan(at, Math.Min(12, line.Length - at)).ToArray(), ticks, ticks));
            ticks += Stopwatch.Frequency / 1000;
        }

        _chunks = chunks.ToArray();
        _capture = Path.Combine(Path.GetTempPath(), $"ohl-monitor-bench-{Environment.ProcessId}.pcap");
    }

    [GlobalCleanup]
    public void Cleanup() => File.Delete(_capture);

    /// <summary>The whole line, every frame through the pipeline; the result is the exchanges formatted.</summary>
    [Benchmark(OperationsPerInvoke = 11 * Rounds)]
    public int Monitor()
    {
        var clock = new MonitorClock();
        int written = 0;
        using CaptureWriter? writer = Capture ? CaptureWriter.Create(_capture) : null;
        var monitor = new LineMonitor(twoPorts: false, clock, writer, e =>
        {
            if (e is MonitorEvent.Exchanged x)
            {
                written += MonitorLineCommand.Human(clock, x.Exchange).Length;
            }
        });
        foreach (TapChunk chunk in _chunks)
        {
            monitor.Take(chunk);
        }

        monitor.Flush(Stopwatch.GetTimestamp());
        return written + _frames;
    }
}
