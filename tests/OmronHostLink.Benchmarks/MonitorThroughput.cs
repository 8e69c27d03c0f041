using System.Diagnostics;
using System.Globalization;
using System.Text;
using OmronHostLink.Cli;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// <c>monitor</c>: how far beyond a saturated 115200 bps line <c>hostlink monitor-line</c> keeps up. A socat pty pair
/// carries golden frames (a one-frame RD and its answer, a 40-word RD answered in two frames, a 50-word WD sent in two,
/// a TS) written into it as fast as the pty takes them; the monitor, in this process as the console runs it, listens on
/// the other end and prints one JSON document an exchange to a file. Reports how long the writing took, how long until
/// the monitor had printed the last exchange, whether it recorded every frame, and the rates against the line's.
/// </summary>
internal static class MonitorThroughput
{
    private static readonly string[] Round =
    [
        "@00RD0000001057*\r", "@00RD00000AFFFF80002F*\r",
        "@00RD0000004052*\r", GoldenFrames.Rd40Frames[0], "\r", GoldenFrames.Rd40Frames[1],
        GoldenFrames.Wd50Frames[0], "\r", GoldenFrames.Wd50Frames[1], "@00WD0053*\r",
        "@00TS==HelloPLC5A*\r", "@00TS==HelloPLC5A*\r",
    ];

    public static async Task<int> RunAsync(string[] args)
    {
        int rounds = args.Length >= 2 && args[0] == "--rounds" ? int.Parse(args[1], CultureInfo.InvariantCulture) : 20000;
        byte[] line = Encoding.ASCII.GetBytes(string.Concat(Enumerable.Repeat(string.Concat(Round), rounds)));
        int frames = Round.Length * rounds;
        int exchanges = 4 * rounds;
        string output = Path.Combine(Path.GetTempPath(), $"ohl-monitor-throughput-{Environment.ProcessId}.jsonl");
        await using SocatPtyPair pair = await SocatPtyPair.StartAsync();
        var stdout = new StreamWriter(output) { AutoFlush = false };
        var stderr = new StringWriter();
        using var stop = new CancellationTokenSource();
        Task<int> monitor = CliApp.RunAsync(["monitor-line", "--port", pair.PathA, "--baud", "115200", "--data-bits", "8", "--parity", "none", "--stop-bits", "1", "--json", "--summary-every", "0"], TextWriter.Synchronized(stdout), TextWriter.Synchronized(stderr), stop.Token);
        while (!stderr.ToString().Contains("Listening", StringComparison.Ordinal))
        {
            await Task.Delay(20);
        }

        var clock = Stopwatch.StartNew();
        using (var writer = new FileStream(pair.PathB, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, bufferSize: 0))
        {
            for (int at = 0; at < line.Length; at += 4096)
            {
                writer.Write(line, at, Math.Min(4096, line.Length - at));
            }

            TimeSpan written = clock.Elapsed;

            // Until the monitor has printed the last exchange (the file is flushed to be looked at).
            while (CountExchanges(stdout, output) < exchanges && clock.Elapsed < TimeSpan.FromMinutes(10))
            {
                await Task.Delay(50);
            }

            TimeSpan processed = clock.Elapsed;
            await stop.CancelAsync();
            await monitor;
            await stdout.DisposeAsync();
            string summary = File.ReadLines(output).Last();
            File.Delete(output);
            double saturated = 115200 / 10.0 / (line.Length / (double)frames);
            Console.WriteLine($"{rounds} rounds: {frames} frames, {exchanges} exchanges, {line.Length} bytes ({line.Length / 11520.0:0} s of a saturated 115200 8N1 line, {saturated:0} frames/s)");
            Console.WriteLine($"written into the pty in {written.TotalSeconds:0.00} s ({frames / written.TotalSeconds:0} frames/s, {frames / written.TotalSeconds / saturated:0}x the line)");
            Console.WriteLine($"all exchanges printed after {processed.TotalSeconds:0.00} s ({frames / processed.TotalSeconds:0} frames/s, {frames / processed.TotalSeconds / saturated:0}x the line)");
            Console.WriteLine($"monitor's summary: {summary}");
            return summary.Contains($"\"frames\":{frames},", StringComparison.Ordinal) && summary.Contains("\"strayFrames\":0,\"noiseBytes\":0", StringComparison.Ordinal) ? 0 : 1;
        }
    }

    private static int CountExchanges(StreamWriter stdout, string path)
    {
        lock (stdout)
        {
            stdout.Flush();
        }

        using var reader = new StreamReader(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite));
        int n = 0;
        while (reader.ReadLine() is { } l)
        {
            n += l.StartsWith("{\"time\"", StringComparison.Ordinal) ? 1 : 0;
        }

        return n;
    }
}
