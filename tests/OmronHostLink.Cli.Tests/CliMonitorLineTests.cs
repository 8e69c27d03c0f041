using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using OmronHostLink.Cli;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli.Tests;

/// <summary>
/// <c>monitor-line</c> on real pseudo-terminals: a client and the simulator talk over a line kept saturated at 115200
/// bps, and the monitor, listening on the line's tap, must record every frame the simulator logged, pair each command with
/// its answer, and report each answer's latency: typically within a millisecond of the simulator's own timestamps, and
/// never further off than a loaded machine can hold a reader back (<see cref="LatencyBound"/>).
/// </summary>
/// <remarks>
/// The session lasts about <c>HOSTLINK_MONITOR_LINE_SECONDS</c> seconds (default 10); the
/// acceptance run is 600 (docs/field-diagnosis.md). The monitor runs as its own process, as a user runs it, on taps this
/// process writes directly (<see cref="PseudoTerminalMaster"/>); the host's socat and the line's relay run with real-time
/// scheduling where Linux allows it, as the monitor's reader does. The five exchanges furthest from the simulator's
/// latency are printed with the figures.
/// </remarks>
[Collection(TimingCollection.Name)]
public sealed class CliMonitorLineTests : IDisposable
{
    private const int Baud = 115200;
    private static readonly string[] LineSettings = ["--baud", "115200", "--data-bits", "8", "--parity", "none", "--stop-bits", "1"];

    private readonly string _dir = Directory.CreateTempSubdirectory("ohl-monitor-").FullName;

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    /// <summary>
    /// The first exchanges of a session, whose latencies are not compared: the first time each path runs (the monitor's
    /// reader, the simulator's answer) it is compiled, which holds one side back by milliseconds. Their frames are
    /// counted and paired like the others.
    /// </summary>
    private const int WarmUp = 50;

    /// <summary>
    /// How far any one latency the monitor reports may be from the simulator's. A passive monitor's timestamp is the time
    /// its read returned, so it is late by as long as the machine kept the reader from running after the bytes came:
    /// nothing with real-time scheduling, but without it (CI need not run as root) a woken reader can wait a scheduler
    /// period — on a 2-core machine with 20 runnable tasks, ten to a core at 1.5 to 3 ms each, 15 to 30 ms — and every
    /// thread of the monitor, real-time or not, waits out a collection of its garbage, whose collector thread has no
    /// real-time priority (75 ms once, with the load average at 9). 250 ms is above both; a mis-paired frame is caught by
    /// its text, compared too. A systematic error (the wrong byte's time: a frame's transmission is 1.5 ms for the
    /// shortest command here) is caught by the median, held to 1 ms, the accuracy the monitor gives an exchange whose
    /// reads were on time.
    /// </summary>
    private static readonly TimeSpan LatencyBound = TimeSpan.FromMilliseconds(250);

    /// <summary>How far the median latency may be from the simulator's (see <see cref="LatencyBound"/>).</summary>
    private static readonly TimeSpan MedianBound = TimeSpan.FromMilliseconds(1);

    /// <summary>How long the saturated session runs.</summary>
    public static TimeSpan SessionLength
        => TimeSpan.FromSeconds(int.TryParse(Environment.GetEnvironmentVariable("HOSTLINK_MONITOR_LINE_SECONDS"), NumberStyles.None, CultureInfo.InvariantCulture, out int s) && s > 0 ? s : 10);

    [Fact]
    [Trait("Category", "Slow")]
    public async Task On_one_port_every_frame_of_a_saturated_line_is_recorded_paired_and_timed()
    {
        await using TappedSerialLine line = await TappedSerialLine.StartAsync(Baud, 10);

        Result result = await MonitorSessionAsync(line, ["--port", line.TapPort!], SessionLength);

        result.Check();
    }

    [Fact]
    [Trait("Category", "Slow")]
    public async Task On_two_ports_every_frame_is_recorded_paired_and_timed()
    {
        await using TappedSerialLine line = await TappedSerialLine.StartAsync(Baud, 10, bothDirections: false, eachDirection: true);

        Result result = await MonitorSessionAsync(line, ["--host-port", line.HostTapPort!, "--plc-port", line.PlcTapPort!], TimeSpan.FromSeconds(5));

        result.Check();
    }

    /// <summary>Runs the monitor on the line's tap while a client keeps the line busy, then gathers what each side recorded.</summary>
    private async Task<Result> MonitorSessionAsync(TappedSerialLine line, string[] where, TimeSpan length)
    {
        var log = new SimulatorFrameLog();
        var plc = new VirtualPlc(new VirtualPlcOptions { FrameLog = log });
        for (int i = 0; i < 100; i++)
        {
            plc.WriteWord(PlcArea.Dm, 100 + i, (ushort)(i * 31));
        }

        // The PLC's end is the line itself (see TappedSerialLine), so the simulator's timestamps are when bytes crossed it.
        await using var host = new SerialSimulatorHost(plc, () => line.PlcStream);
        await host.StartAsync();

        // The monitor runs as a user runs it, a process of its own: its timestamps owe nothing to this process's
        // collections of the client's and the simulator's garbage.
        string capture = Path.Combine(_dir, "monitor.pcap");
        await using HostlinkProcess monitor = HostlinkProcess.Start(["monitor-line", .. where, .. LineSettings, "--json", "--summary-every", "0", "--capture", capture]);
        await monitor.ExpectOutputAsync("Listening", TimeSpan.FromSeconds(30), onStandardError: true);

        // The clients are processes of their own too: their garbage is not collected in the process whose simulator
        // stamps the reference times. Divided answers (RD of 60 words, polled back to back), FINS reads, a divided
        // command (WD of 40 words), TS and MS.
        string[] port = ["--port", line.HostPort, .. LineSettings];
        int polls = (int)Math.Max(30, length.TotalSeconds * 35);
        await ClientAsync(["monitor", "D100", "60", "--interval", "0", "--count", polls.ToString(CultureInfo.InvariantCulture), .. port]);
        await ClientAsync(["monitor", "D101", "2", "--fins", "--interval", "0", "--count", (polls / 4).ToString(CultureInfo.InvariantCulture), .. port]);
        await ClientAsync(["write", "D300", .. Enumerable.Range(7, 40).Select(i => i.ToString(CultureInfo.InvariantCulture)), .. port]);
        await ClientAsync(["test", "SATURATED", .. port]);
        await ClientAsync(["status", .. port]);

        long logged = log.Count;
        await Eventually.UntilAsync(
            () => FramesIn(monitor.Out) >= logged,
            "the monitor hears the last frames",
            () => string.Create(CultureInfo.InvariantCulture, $"{FramesIn(monitor.Out)} of {logged} frames; strays and noise: {string.Join(" ", monitor.Out.Split('\n').Where(l => l.Contains("\"stray\"", StringComparison.Ordinal) || l.Contains("\"noise\"", StringComparison.Ordinal)).Take(5))}; {monitor.Err}"));
        (await monitor.StopAsync(TimeSpan.FromSeconds(10))).Should().BeTrue("the monitor stops cleanly on SIGTERM");
        await host.StopAsync();
        string[] documents = monitor.Out.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        return new Result(monitor.ExitCode, monitor.Err, documents, capture, log.Frames);
    }

    private static async Task ClientAsync(string[] args)
    {
        CliResult r = await HostlinkProcess.RunAsync(TimeSpan.FromHours(1), args);
        r.ExitCode.Should().Be(0, "the client's {0} works: {1}", args[0], r);
    }

    private static long FramesIn(string output)
    {
        long frames = 0;
        foreach (string line in output.Split('\n', StringSplitOptions.RemoveEmptyEntries))
        {
            if (line.Contains("\"command\":[", StringComparison.Ordinal))
            {
                using JsonDocument doc = JsonDocument.Parse(line);
                frames += doc.RootElement.GetProperty("command").GetArrayLength() + doc.RootElement.GetProperty("answer").GetArrayLength();
            }
        }

        return frames;
    }

    /// <summary>What the simulator logged and what the monitor printed and captured.</summary>
    private sealed record Result(int Exit, string Errors, string[] Output, string CapturePath, IReadOnlyList<SimulatorFrame> Logged)
    {
        public void Check()
        {
            Exit.Should().Be(0, Errors);
            List<JsonElement> documents = Output.Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToList();
            List<JsonElement> exchanges = documents.Where(d => d.TryGetProperty("command", out _)).ToList();
            documents.Where(d => d.TryGetProperty("stray", out _) || d.TryGetProperty("noise", out _)).Should().BeEmpty("every byte on the line belongs to an exchange");

            // The simulator's log cut into exchanges: a frame from the host that starts with '@' starts one.
            var expected = new List<(List<SimulatorFrame> Command, List<SimulatorFrame> Answer)>();
            foreach (SimulatorFrame f in Logged)
            {
                if (f.FromHost && f.Bytes.Span[0] == (byte)'@')
                {
                    expected.Add((new List<SimulatorFrame>(), new List<SimulatorFrame>()));
                }

                (f.FromHost ? expected[^1].Command : expected[^1].Answer).Add(f);
            }

            long monitored = exchanges.Sum(x => x.GetProperty("command").GetArrayLength() + x.GetProperty("answer").GetArrayLength());
            monitored.Should().Be(Logged.Count, "the monitor records every frame the simulator logged");
            exchanges.Should().HaveCount(expected.Count);

            IReadOnlyList<Capture.CapturedFrame> captured = Capture.CaptureReader.Read(CapturePath);
            captured.Should().HaveCount(Logged.Count, "the capture holds every frame too");
            captured.Select(c => c.Direction == Capture.LineDirection.ToPlc).Should().Equal(Logged.Select(f => f.FromHost));

            var differences = new List<(double Ms, string What)>();
            for (int i = 0; i < expected.Count; i++)
            {
                JsonElement x = exchanges[i];
                (List<SimulatorFrame> command, List<SimulatorFrame> answer) = expected[i];
                x.GetProperty("command").EnumerateArray().Select(e => e.GetString()).Should().Equal(command.Select(f => f.Text), "exchange {0}'s command", i);
                x.GetProperty("answer").EnumerateArray().Select(e => e.GetString()).Should().Equal(answer.Select(f => f.Text), "exchange {0}'s answer", i);
                x.GetProperty("status").GetString().Should().Be("ok", "exchange {0}", i);

                x.GetProperty("latencyMs").ValueKind.Should().Be(JsonValueKind.Number, "exchange {0}'s latency is reported", i);
                SimulatorFrame first = answer.First(f => f.Bytes.Span[0] == (byte)'@');
                SimulatorFrame lastCommand = command.Where(f => f.Time <= first.FirstByteTime).OrderBy(f => f.Time).Last();
                TimeSpan simulator = first.FirstByteTime - lastCommand.Time;
                var heard = TimeSpan.FromMilliseconds(x.GetProperty("latencyMs").GetDouble());
                if (i < WarmUp)
                {
                    continue;
                }

                differences.Add(((heard - simulator).TotalMilliseconds, $"exchange {i} ({x.GetProperty("header").GetString()}): the monitor heard {heard.TotalMilliseconds:0.000} ms, the simulator logged {simulator.TotalMilliseconds:0.000} ms"));
            }

            double[] sorted = differences.Select(d => Math.Abs(d.Ms)).Order().ToArray();
            double bound = LatencyBound.TotalMilliseconds;
            Console.WriteLine($"monitor-line: {expected.Count} exchanges, {Logged.Count} frames; after {WarmUp} warm-up exchanges, |monitor - simulator| latency: median {sorted[sorted.Length / 2]:0.000} ms, 99th percentile {sorted[(int)(sorted.Length * 0.99)]:0.000} ms, worst {sorted[^1]:0.000} ms, over 1 ms: {sorted.Count(d => d > 1)}");
            foreach ((double ms, string what) in differences.OrderByDescending(d => Math.Abs(d.Ms)).Take(5))
            {
                Console.WriteLine($"  {ms:+0.000;-0.000} ms: {what}");
            }

            sorted[sorted.Length / 2].Should().BeLessThanOrEqualTo(MedianBound.TotalMilliseconds, "a typical answer latency the monitor heard is within a millisecond of the simulator's own");
            differences.Where(d => Math.Abs(d.Ms) > bound).Select(d => d.What).Should().BeEmpty("every answer latency the monitor heard is within {0} ms of the simulator's own (see LatencyBound)", bound);
        }
    }
}
