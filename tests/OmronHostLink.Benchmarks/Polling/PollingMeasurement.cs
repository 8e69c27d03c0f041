using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Text.Json.Nodes;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;
using OmronHostLink.Transports;

namespace OmronHostLink.Benchmarks.Polling;

/// <summary>
/// <c>polling</c> mode: the gateway as a plant runs it after a Kepware migration — one tag file of scattered words and
/// bits, every row at one scan rate, on one emulated serial line (a serial-device server paced both ways). Several
/// gateways run side by side, each a separate process on a line of its own: the gateway built with this benchmark with
/// QQ automatic (the default) and with <c>UseCompoundRead: Off</c>, and, with <c>--before</c>, another build (the one
/// before planned polling). Each tag's refresh, the commands and the line's busy bursts are measured at the PLC: every
/// command it receives is decoded and each word it reads stamped (<see cref="CommandTap"/>), whichever gateway asked.
/// </summary>
internal static class PollingMeasurement
{
    private const int Bits = 11;

    // A busy burst (a cycle, where cycles leave the line a rest) ends after this long without a character.
    private static readonly TimeSpan Quiet = TimeSpan.FromMilliseconds(40);

    public static async Task<int> RunAsync(string[] args)
    {
        int tags = 100;
        int baud = 9600;
        TimeSpan interval = TimeSpan.FromSeconds(1);
        int seconds = 60;
        int warmup = 10;
        string? before = null;
        string? worker = null;
        string[] only = ["before", "auto", "off"];
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--tags":
                    tags = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--baud":
                    baud = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--interval":
                    interval = Duration.Parse(args[++i]);
                    break;
                case "--seconds":
                    seconds = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--warmup":
                    warmup = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--before":
                    before = args[++i];
                    break;
                case "--worker":
                    worker = args[++i];
                    break;
                case "--variants":
                    only = args[++i].Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
                    break;
                default:
                    Console.Error.WriteLine($"polling: unknown argument {args[i]}");
                    Console.Error.WriteLine("usage: polling [--tags 100] [--baud 9600] [--interval 1s] [--seconds 60] [--warmup 10] [--before path/OmronHostLink.Gateway.dll] [--worker path] [--variants before,auto,off]");
                    return 2;
            }
        }

        ScatteredTagFile.Tag[] generated = ScatteredTagFile.Generate(tags, seed: 42);
        string directory = ProgramProcess.NewDirectory("ohl-polling-");
        string file = Path.Combine(directory, "tags.csv");
        await File.WriteAllTextAsync(file, ScatteredTagFile.Csv(generated, (int)interval.TotalMilliseconds));

        var timing = new LineTiming(baud, Bits);
        PlcTag[] words = GatewayTags(generated);
        ReadPlan areaPlan = new ReadPlanner(HostLinkCommandSet.CMode, timing) { UseCompoundRead = CompoundReadMode.Off }.Plan(words);
        ReadPlan qqPlan = new ReadPlanner(HostLinkCommandSet.CMode, timing) { Model = PlcModelProfile.Parse("CS1") }.Plan(words);
        Console.WriteLine($"# Polling: {Environment.ProcessorCount} cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.FrameworkDescription}, {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC; load average {ProcessSample.LoadAverage():0.0}");
        Console.WriteLine($"# {generated.Length} scattered tags (seed 42: {Kinds(generated)}) from one Kepware export, all at {interval.TotalSeconds:0.###} s, unit 0 of a CS/CJ (the simulator) on its own {baud} bps line (11 bits/char, paced both ways, turnaround 0)");
        Console.WriteLine($"# planner: QQ {qqPlan}; area reads {areaPlan}");
        Console.WriteLine($"# {warmup} s after every tag's first read, {seconds} s measured; each gateway a separate process on its own line, all at once");
        Console.WriteLine();

        var variants = new List<Variant>();
        if (before is not null && only.Contains("before"))
        {
            variants.Add(new Variant("before (one watch a row)", WorkerProcess.Locate(before), null));
        }

        string current = WorkerProcess.Locate(worker);
        if (only.Contains("auto"))
        {
            variants.Add(new Variant("planned, QQ automatic", current, null));
        }

        if (only.Contains("off"))
        {
            variants.Add(new Variant("planned, UseCompoundRead Off", current, "Off"));
        }

        using var clock = new LineClock();
        var runs = new List<Run>();
        try
        {
            foreach (Variant v in variants)
            {
                var ledger = new CommandLedger((double)Bits / baud * Stopwatch.Frequency, Quiet);
                var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
                Fill(plc, generated);
                SerialDeviceServer server = SerialDeviceServer.Start(plc, baud, Bits, clock, line => new CommandTap(line, ledger));
                WorkerProcess process = await WorkerProcess.StartAsync(v.Assembly, Settings(server.Port, baud, file, v.CompoundRead), CancellationToken.None);
                runs.Add(new Run(v, server, ledger, process));
            }

            // Ready when every tag has been read at least once on every line.
            var patience = Stopwatch.StartNew();
            while (runs.Any(r => generated.Any(t => r.Ledger.ReadTimes(ScatteredTagFile.Keys(t, 0).First()).Length == 0)))
            {
                foreach (Run r in runs.Where(r => r.Process.HasExited))
                {
                    throw new InvalidOperationException($"{r.Variant.Name}: the gateway exited:\n{r.Process.Output}");
                }

                if (patience.Elapsed > TimeSpan.FromSeconds(120))
                {
                    throw new InvalidOperationException("Not every tag was read within 120 s:\n" + string.Join("\n", runs.Select(r => r.Variant.Name + ":\n" + r.Process.Output)));
                }

                await Task.Delay(200);
            }

            await Task.Delay(TimeSpan.FromSeconds(warmup));
            var starts = runs.Select(r => (Cpu: ProcessSample.Read(r.Process.Id) ?? default, Commands: r.Ledger.Headers)).ToArray();
            long t0 = Stopwatch.GetTimestamp();
            await Task.Delay(TimeSpan.FromSeconds(seconds));
            long t1 = Stopwatch.GetTimestamp();
            double elapsed = (t1 - t0) / (double)Stopwatch.Frequency;

            Console.WriteLine("| Gateway | Commands/s (per cycle) | Commands by header | Per-tag time between reads: mean of all / worst tag / reads of the least-read tag | Tags read every ≤ 1.1 × interval | Cycle (busy burst) p50 / max ms | Gateway CPU % of a core |");
            Console.WriteLine("|---|---|---|---|---|---|---|");
            for (int i = 0; i < runs.Count; i++)
            {
                Run r = runs[i];
                ProcessSample cpu = ProcessSample.Read(r.Process.Id) ?? default;
                IReadOnlyDictionary<string, long> headers = r.Ledger.Headers;
                Dictionary<string, long> window = headers.ToDictionary(h => h.Key, h => h.Value - starts[i].Commands.GetValueOrDefault(h.Key));
                double commands = window.Values.Sum() / elapsed;
                double[] means = generated.Select(t => MeanInterval(r.Ledger.ReadTimes(ScatteredTagFile.Keys(t, 0).First()), t0, t1)).ToArray();
                int[] counts = generated.Select(t => r.Ledger.ReadTimes(ScatteredTagFile.Keys(t, 0).First()).Count(x => x >= t0 && x < t1)).ToArray();
                double[] bursts = r.Ledger.BurstsMs(t0, t1).Order().ToArray();
                int onTime = means.Count(m => m <= 1.1 * interval.TotalSeconds);
                Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
                    $"| {r.Variant.Name} | {commands:0.0} ({commands * interval.TotalSeconds:0.0}) | {string.Join(", ", window.Where(h => h.Value > 0).OrderByDescending(h => h.Value).Select(h => $"{h.Key} {h.Value}"))} | {means.Average():0.000} s / {means.Max():0.000} s / {counts.Min()} | {onTime} of {means.Length} | {(means.Average() > 1.1 * interval.TotalSeconds ? "— (never rests)" : $"{Percentile(bursts, 0.5):0} / {(bursts.Length == 0 ? double.NaN : bursts[^1]):0}")} | {cpu.CpuPercentSince(starts[i].Cpu, elapsed):0.0} |"));
            }

            Console.WriteLine();
            Console.WriteLine($"<!-- window {elapsed:0.0} s; load average at the end {ProcessSample.LoadAverage():0.0}; planner estimates at {baud} bps: QQ {qqPlan.EstimatedTime.TotalMilliseconds:0} ms, area reads {areaPlan.EstimatedTime.TotalMilliseconds:0} ms a cycle -->");
            foreach (Run r in runs)
            {
                foreach (string line in r.Process.Lines.Where(l => l.Contains("plan", StringComparison.OrdinalIgnoreCase) || l.StartsWith("warn:", StringComparison.Ordinal)).Take(12))
                {
                    Console.WriteLine($"<!-- {r.Variant.Name}: {line} -->");
                }
            }
        }
        finally
        {
            foreach (Run r in runs)
            {
                await r.Process.StopAsync();
                await r.Process.DisposeAsync();
                await r.Server.DisposeAsync();
            }

            Directory.Delete(directory, recursive: true);
        }

        return 0;
    }

    /// <summary>The tags as the gateway reads them: each word of a row (bits by their word), completion flags as flags.</summary>
    internal static PlcTag[] GatewayTags(IEnumerable<ScatteredTagFile.Tag> tags, int? unit = null)
        => tags.SelectMany(t => t.CompletionFlag
            ? [new PlcTag(PlcAddress.WordOf(t.Area, t.Word), PlcValueType.Bit, unit)]
            : Enumerable.Range(0, t.Words).Select(i => new PlcTag(PlcAddress.WordOf(t.Area, t.Word + i), PlcValueType.Word, unit))).ToArray();

    internal static void Fill(VirtualPlc plc, IEnumerable<ScatteredTagFile.Tag> tags)
    {
        foreach (ScatteredTagFile.Tag t in tags.Where(t => !t.CompletionFlag))
        {
            for (int i = 0; i < t.Words; i++)
            {
                plc.WriteWord(t.Area, t.Word + i, (ushort)(t.Word + i));
            }
        }
    }

    /// <summary>The mean time between the reads of a word in the window, in seconds; infinity when read less than twice.</summary>
    internal static double MeanInterval(long[] times, long from, long to)
    {
        long[] inWindow = times.Where(t => t >= from && t < to).ToArray();
        return inWindow.Length < 2 ? double.PositiveInfinity : (inWindow[^1] - inWindow[0]) / (double)Stopwatch.Frequency / (inWindow.Length - 1);
    }

    internal static double Percentile(double[] sorted, double p)
        => sorted.Length == 0 ? double.NaN : sorted[Math.Clamp((int)Math.Ceiling(p * sorted.Length) - 1, 0, sorted.Length - 1)];

    private static string Kinds(ScatteredTagFile.Tag[] tags)
        => string.Join(", ", tags.GroupBy(t => (t.KepwareType, t.Area)).OrderByDescending(g => g.Count()).Select(g => $"{g.Count()} {g.Key.KepwareType} in {g.Key.Area}"));

    private static JsonObject Settings(int port, int baud, string file, string? compoundRead)
    {
        var link = new JsonObject
        {
            ["Tcp"] = $"127.0.0.1:{port}",
            ["Serial"] = new JsonObject { ["BaudRate"] = baud },
            ["TagFiles"] = new JsonArray(new JsonObject { ["Path"] = file, ["Format"] = "Kepware", ["Unit"] = 0, ["Log"] = "OnChange" }),
        };
        if (compoundRead is not null)
        {
            link["UseCompoundRead"] = compoundRead;
        }

        return new JsonObject
        {
            ["Logging"] = new JsonObject
            {
                ["LogLevel"] = new JsonObject { ["Default"] = "Warning", ["OmronHostLink.Gateway"] = "Information", ["OmronHostLink"] = "Information" },
                ["Console"] = new JsonObject { ["FormatterName"] = "simple", ["FormatterOptions"] = new JsonObject { ["SingleLine"] = true } },
            },
            ["HostLink"] = new JsonObject { ["Links"] = new JsonObject { ["plc"] = link } },
        };
    }

    private sealed record Variant(string Name, string Assembly, string? CompoundRead);

    private sealed record Run(Variant Variant, SerialDeviceServer Server, CommandLedger Ledger, WorkerProcess Process);
}
