using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Statistics;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Polling;

/// <summary>
/// <c>mixed</c> mode: the gateway in process, 1,000 tags on 4 links × 2 units at mixed scan classes — per unit a block
/// of 5 words every 100 ms, 40 scattered words every 1 s, 80 scattered words every 10 s — each link an emulated
/// serial-device server paced both ways. Measured over a long window: each tag's mean time between reads at the PLC
/// (no tag starves), each scan class's time on the line a cycle (at the PLC: from each of its commands to its last
/// answer frame) against the plan's own time on the line, its cycle time as the gateway measures it (waits for the
/// line included) against the plan's expected cycle on the shared line, and the process's memory over the window (after a full collection, every 30 s).
/// </summary>
internal static class MixedScanMeasurement
{
    private const int Bits = 11;

    private static readonly (TimeSpan Interval, int Tags, bool Block)[] Classes =
    [
        (TimeSpan.FromMilliseconds(100), 5, true),
        (TimeSpan.FromSeconds(1), 40, false),
        (TimeSpan.FromSeconds(10), 80, false),
    ];

    public static async Task<int> RunAsync(string[] args)
    {
        int links = 4;
        int units = 2;
        int baud = 38400;
        TimeSpan window = TimeSpan.FromMinutes(10);
        TimeSpan warmup = TimeSpan.FromSeconds(30);
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--links":
                    links = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--units":
                    units = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--baud":
                    baud = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--window":
                    window = Duration.Parse(args[++i]);
                    break;
                case "--warmup":
                    warmup = Duration.Parse(args[++i]);
                    break;
                default:
                    Console.Error.WriteLine($"mixed: unknown argument {args[i]}");
                    Console.Error.WriteLine("usage: mixed [--links 4] [--units 2] [--baud 38400] [--window 10m] [--warmup 30s]");
                    return 2;
            }
        }

        // Per unit: the words of each class, disjoint (the 100 ms block at 5000 + 10 × unit; the others scattered).
        var random = new Random(42);
        var tags = new List<(int Link, int Unit, TimeSpan Interval, int Word)>();
        for (int link = 0; link < links; link++)
        {
            for (int unit = 0; unit < units; unit++)
            {
                var used = new HashSet<int>();
                foreach ((TimeSpan interval, int count, bool block) in Classes)
                {
                    for (int t = 0; t < count; t++)
                    {
                        int word = block ? 5000 + (10 * unit) + t : random.Next(0, 4900);
                        while (!block && !used.Add(word))
                        {
                            word = random.Next(0, 4900);
                        }

                        tags.Add((link, unit, interval, word));
                    }
                }
            }
        }

        using var clock = new LineClock();
        var servers = new List<SerialDeviceServer>();
        var ledgers = new List<CommandLedger>();
        var config = new Dictionary<string, string?>
        {
            ["Logging:LogLevel:Default"] = "Warning",
        };
        for (int link = 0; link < links; link++)
        {
            int l = link;
            var classOf = tags.Where(t => t.Link == l).ToDictionary(t => new CommandLedger.ReadKey(t.Unit, PlcArea.Dm, 0, t.Word, false), t => Name(t.Unit, t.Interval));
            var ledger = new CommandLedger((double)Bits / baud * Stopwatch.Frequency, TimeSpan.FromMilliseconds(40), keepTimes: false, classify: k => classOf.GetValueOrDefault(k));
            ledgers.Add(ledger);
            var plc = new VirtualPlc(new VirtualPlcOptions { Units = [.. Enumerable.Range(0, units)] });
            for (int w = 0; w < 5100; w++)
            {
                plc.WriteWord(PlcArea.Dm, w, (ushort)w);
            }

            SerialDeviceServer server = SerialDeviceServer.Start(plc, baud, Bits, clock, line => new CommandTap(line, ledger));
            servers.Add(server);
            string prefix = $"HostLink:Links:line{link}:";
            config[prefix + "Tcp"] = $"127.0.0.1:{server.Port}";
            config[prefix + "Serial:BaudRate"] = baud.ToString(CultureInfo.InvariantCulture);
            foreach ((int _, int unit, TimeSpan interval, int word) in tags.Where(t => t.Link == l))
            {
                string g = $"{prefix}Groups:u{unit}d{word}:";
                config[g + "Unit"] = unit.ToString(CultureInfo.InvariantCulture);
                config[g + "Address"] = $"D{word}";
                config[g + "Interval"] = interval.ToString("c", CultureInfo.InvariantCulture);
                config[g + "Log"] = "OnChange";
            }
        }

        Console.WriteLine($"# Mixed scan classes: {Environment.ProcessorCount} cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.FrameworkDescription}, {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC; load average {ProcessSample.LoadAverage():0.0}");
        Console.WriteLine($"# {tags.Count} tags on {links} links × {units} units, each link an emulated {baud} bps line (11 bits/char, paced both ways, turnaround 0); per unit: {string.Join(", ", Classes.Select(c => $"{c.Tags} {(c.Block ? "consecutive" : "scattered")} words every {Text(c.Interval)}"))}");
        Console.WriteLine($"# the gateway in process (QQ automatic); {warmup.TotalSeconds:0} s warm-up, then {window.TotalMinutes:0.#} min measured");

        var configuration = new ConfigurationManager();
        configuration.AddInMemoryCollection(config);
        HostApplicationBuilder builder = GatewayHost.CreateBuilder(new HostApplicationBuilderSettings
        {
            DisableDefaults = true,
            EnvironmentName = "Production",
            ContentRootPath = AppContext.BaseDirectory,
            Configuration = configuration,
        });
        using IHost host = builder.Build();
        await host.StartAsync();
        LinkStatistics statistics = host.Services.GetRequiredService<LinkStatistics>();
        await Task.Delay(warmup);

        ledgers.ForEach(l => l.ResetStats());
        Dictionary<string, ScanClassStatistics> start = Snapshot(statistics, links);
        var memory = new List<(double Minutes, double HeapMb, double RssMb)>();
        var clockWindow = Stopwatch.StartNew();
        while (clockWindow.Elapsed < window)
        {
            // The emulated lines' own pacing samples are the benchmark's, not the gateway's: dropped before each count.
            servers.ForEach(s => s.TakeSamples());
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();
            memory.Add((clockWindow.Elapsed.TotalMinutes, GC.GetTotalMemory(false) / 1048576.0, (ProcessSample.Read(Environment.ProcessId)?.RssKilobytes ?? 0) / 1024.0));
            TimeSpan left = window - clockWindow.Elapsed;
            if (left > TimeSpan.Zero)
            {
                await Task.Delay(left < TimeSpan.FromSeconds(30) ? left : TimeSpan.FromSeconds(30));
            }
        }

        double elapsed = clockWindow.Elapsed.TotalSeconds;
        servers.ForEach(s => s.TakeSamples());
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
        memory.Add((clockWindow.Elapsed.TotalMinutes, GC.GetTotalMemory(false) / 1048576.0, (ProcessSample.Read(Environment.ProcessId)?.RssKilobytes ?? 0) / 1024.0));
        Dictionary<string, ScanClassStatistics> end = Snapshot(statistics, links);
        var perLine = ledgers.Select(l => l.Classes).ToArray();
        var tagStats = tags.Select(t => (t, s: ledgers[t.Link].StatsOf(new CommandLedger.ReadKey(t.Unit, PlcArea.Dm, 0, t.Word, false)))).ToArray();
        await host.StopAsync();
        foreach (SerialDeviceServer server in servers)
        {
            await server.DisposeAsync();
        }

        Console.WriteLine();
        Console.WriteLine("| Scan class | Classes | Reads a cycle (plan) | Plan's own time on the line ms | Time on the line a cycle, at the PLC: ms (÷ plan's own), min–max | Plan's expected cycle on the shared line ms | Gateway's cycle ms (÷ expected), min–max | Overruns in the window | Tags: mean time between reads, worst ÷ interval | Longest gap between two reads of a tag |");
        Console.WriteLine("|---|---|---|---|---|---|---|---|---|---|");
        foreach ((TimeSpan interval, int _, bool _) in Classes)
        {
            var rows = new List<(int Reads, double Own, double Line, double Estimate, double Cycle, long Overruns)>();
            for (int link = 0; link < links; link++)
            {
                for (int unit = 0; unit < units; unit++)
                {
                    string key = $"line{link}|{Name(unit, interval)}";
                    ScanClassStatistics a = start[key];
                    ScanClassStatistics b = end[key];
                    long cycles = b.Cycles - a.Cycles;
                    double cycleMs = ((b.AverageCycleMs ?? 0) * b.Cycles - (a.AverageCycleMs ?? 0) * a.Cycles) / cycles;
                    (long commands, long ticks) = perLine[link].GetValueOrDefault(Name(unit, interval));
                    double lineMs = ticks * 1000.0 / Stopwatch.Frequency / cycles;
                    rows.Add((b.Reads, b.LineTimeMs, lineMs, b.EstimatedCycleMs, cycleMs, b.Overruns - a.Overruns));
                }
            }

            var ofClass = tagStats.Where(x => x.t.Interval == interval).ToArray();
            double worstMean = ofClass.Max(x => x.s?.MeanSeconds ?? double.PositiveInfinity);
            double worstGap = ofClass.Max(x => (x.s?.MaxGap ?? long.MaxValue) / (double)Stopwatch.Frequency);
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                $"| every {Text(interval)} | {rows.Count} | {string.Join("/", rows.Select(r => r.Reads).Distinct().Order())} | {rows.Min(r => r.Own):0.0}–{rows.Max(r => r.Own):0.0} | {rows.Average(r => r.Line):0.0} ({rows.Average(r => r.Line / r.Own):P1}), {rows.Min(r => r.Line / r.Own):P1}–{rows.Max(r => r.Line / r.Own):P1} | {rows.Min(r => r.Estimate):0.0}–{rows.Max(r => r.Estimate):0.0} | {rows.Average(r => r.Cycle):0.0} ({rows.Average(r => r.Cycle / r.Estimate):P1}), {rows.Min(r => r.Cycle / r.Estimate):P1}–{rows.Max(r => r.Cycle / r.Estimate):P1} | {rows.Sum(r => r.Overruns)} | {worstMean / interval.TotalSeconds:0.000} | {worstGap:0.000} s |"));
        }

        Console.WriteLine();
        Console.WriteLine("| Scan class | Expected cycle ms, each link's unit 0 / unit 1 | Gateway's cycle ms (÷ expected) |");
        Console.WriteLine("|---|---|---|");
        foreach ((TimeSpan interval, int _, bool _) in Classes)
        {
            var cells = new List<string>();
            var measured = new List<string>();
            for (int link = 0; link < links; link++)
            {
                for (int unit = 0; unit < units; unit++)
                {
                    string key = $"line{link}|{Name(unit, interval)}";
                    ScanClassStatistics a = start[key];
                    ScanClassStatistics b = end[key];
                    double cycleMs = ((b.AverageCycleMs ?? 0) * b.Cycles - (a.AverageCycleMs ?? 0) * a.Cycles) / (b.Cycles - a.Cycles);
                    cells.Add(string.Create(CultureInfo.InvariantCulture, $"{b.EstimatedCycleMs:0}"));
                    measured.Add(string.Create(CultureInfo.InvariantCulture, $"{cycleMs:0} ({cycleMs / b.EstimatedCycleMs:P0})"));
                }
            }

            Console.WriteLine($"| every {Text(interval)} | {string.Join(" / ", cells)} | {string.Join(" / ", measured)} |");
        }

        Console.WriteLine();
        Console.WriteLine("| Minutes into the window | GC heap after a full collection, MB | RSS, MB |");
        Console.WriteLine("|---|---|---|");
        foreach ((double minutes, double heap, double rss) in memory)
        {
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"| {minutes:0.0} | {heap:0.00} | {rss:0} |"));
        }

        Console.WriteLine();
        Console.WriteLine($"<!-- window {elapsed:0} s; load average at the end {ProcessSample.LoadAverage():0.0}; the GC heap and RSS are the whole process: the gateway, the simulated PLCs and their lines, and this benchmark's running figures (constant in size) -->");
        return 0;
    }

    private static string Text(TimeSpan time)
        => time < TimeSpan.FromSeconds(1) ? $"{time.TotalMilliseconds:0} ms" : $"{time.TotalSeconds:0.###} s";

    private static string Name(int unit, TimeSpan interval) => $"u{unit} {interval.TotalMilliseconds:0}ms";

    private static Dictionary<string, ScanClassStatistics> Snapshot(LinkStatistics statistics, int links)
    {
        var snapshot = new Dictionary<string, ScanClassStatistics>(StringComparer.Ordinal);
        for (int link = 0; link < links; link++)
        {
            foreach (ScanClassStatistics s in statistics.Link($"line{link}").ScanClasses)
            {
                snapshot[$"line{link}|{Name(s.Unit, TimeSpan.FromMilliseconds(s.IntervalMs))}"] = s;
            }
        }

        return snapshot;
    }
}
