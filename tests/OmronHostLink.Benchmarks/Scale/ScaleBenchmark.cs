using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using System.Text.Json.Nodes;
using OmronHostLink.Transports;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// <c>scale</c> mode: the worker as a plant gateway. For each N: Mosquitto on a free loopback port, N emulated
/// serial-device servers (a <see cref="VirtualPlc"/> each, behind a line paced at 9600 7E2 both ways), the worker as a
/// separate process with N links of scattered one-word tags polled every second and published to the broker, a writer
/// changing every tag on a fixed schedule, and a subscriber on <c>{prefix}/#</c> matching what arrives to what was
/// written. Reports throughput, the worker's CPU and memory, latency, losses and overruns.
/// </summary>
internal static class ScaleBenchmark
{
    private const int BitsPerCharacter = 11;
    private const string Prefix = "scale";

    /// <summary>Scattered across D so that no two can share a read (the planner merges only gaps of a few words).</summary>
    private static readonly int[] ScatteredWords = [0, 37, 120, 260, 400, 777, 1000, 1500, 2222, 3000];

    public static async Task<int> RunAsync(string[] args)
    {
        Settings settings;
        try
        {
            settings = Settings.Parse(args);
        }
        catch (Exception e) when (e is FormatException or ArgumentException)
        {
            Console.Error.WriteLine($"scale: {e.Message}");
            Console.Error.WriteLine("usage: scale [--links 1,10,50,100] [--seconds 60] [--warmup 5] [--tags 10] [--interval 1] [--change-every 2] [--baud 9600] [--worker path/OmronHostLink.Gateway.dll]");
            return 2;
        }

        using var stop = new CancellationTokenSource();
        Console.CancelKeyPress += (_, e) =>
        {
            e.Cancel = true;
            stop.Cancel();
        };
        using PosixSignalRegistration sigterm = PosixSignalRegistration.Create(PosixSignal.SIGTERM, context =>
        {
            context.Cancel = true;
            stop.Cancel();
        });

        string worker = WorkerProcess.Locate(settings.Worker);
        int[] words = Words(settings.Tags);
        PrintPreamble(settings, worker, words);

        var rows = new List<string>();
        var notes = new List<string>();
        try
        {
            foreach (int links in settings.Links)
            {
                Result r = await RunOneAsync(settings, worker, links, words, stop.Token);
                rows.Add(r.Row);
                notes.Add(r.Note);
                Console.WriteLine(r.Row);
                Console.WriteLine(r.Note);
                Console.Out.Flush();
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            Console.Error.WriteLine("scale: stopped; children ended.");
            return 130;
        }

        Console.WriteLine();
        Console.WriteLine(Header);
        Console.WriteLine(HeaderRule);
        rows.ForEach(Console.WriteLine);
        Console.WriteLine();
        notes.ForEach(Console.WriteLine);
        return 0;
    }

    private const string Header = "| Links | Tags | Transactions/s (expected) | Line busy per link | Host gap p50 ms | Worker CPU % of a core | Worker RSS max MB | Change→subscriber p50 / p99 ms | Read→subscriber p50 / p99 ms | Changes / lost | Cycle overruns | Broker CPU % | Benchmark CPU % | Load avg 1 min (start → end) |";

    private const string HeaderRule = "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|";

    private static int[] Words(int tags)
        => tags <= ScatteredWords.Length
            ? ScatteredWords[..tags]
            : Enumerable.Range(0, tags).Select(i => i * 97).ToArray();

    private static void PrintPreamble(Settings s, string worker, int[] words)
    {
        int chars = ReadPlanner.CModeReadCharacters(PlcArea.Dm, 1, out _);
        double tagMs = chars * BitsPerCharacter * 1000.0 / s.Baud;
        PlcTag[] tags = words.Select(w => new PlcTag($"D{w}", PlcValueType.Word)).ToArray();
        ReadPlan plan = new ReadPlanner(HostLinkCommandSet.CMode, new LineTiming(s.Baud, BitsPerCharacter)) { UseCompoundRead = CompoundReadMode.Off }.Plan(tags);
        double busy = plan.Characters * BitsPerCharacter * 1000.0 / s.Baud;

        Console.WriteLine($"# Scale: worker → MQTT. {Environment.ProcessorCount} cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.FrameworkDescription}, {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC");
        Console.WriteLine($"# worker: {worker}; mosquitto on 127.0.0.1; serial-device servers paced at {s.Baud} 7E2 ({BitsPerCharacter} bits/char) both ways, turnaround 0");
        Console.WriteLine($"# per link: {words.Length} one-word tags ({string.Join(", ", words.Select(w => "D" + w))}) polled every {s.Interval.TotalSeconds:0.###} s, C-mode RD; each tag changed every {s.ChangeEvery.TotalSeconds:0.###} s; {s.Seconds} s measured after {s.Warmup} s warm-up");
        Console.WriteLine($"# line time: one-word RD = {chars} characters × {BitsPerCharacter} / {s.Baud} = {tagMs:0.00} ms; the planner makes {plan.TransactionCount} reads of these {words.Length} tags = {busy:0} ms per cycle;");
        Console.WriteLine($"#   a {s.Baud} line saturates at {Math.Floor(s.Interval.TotalMilliseconds / tagMs)} scattered tags per {s.Interval.TotalSeconds:0.###} s interval (turnaround 0; a real PLC's turnaround of t ms: {s.Interval.TotalMilliseconds:0} / ({tagMs:0.0} + t))");
        Console.WriteLine();
        Console.WriteLine(Header);
        Console.WriteLine(HeaderRule);
    }

    private static async Task<Result> RunOneAsync(Settings s, string workerAssembly, int links, int[] words, CancellationToken cancellationToken)
    {
        double loadStart = ProcessSample.LoadAverage();
        int tagsTotal = links * words.Length;
        int maxChanges = (int)Math.Ceiling(s.Seconds / s.ChangeEvery.TotalSeconds) + 1;
        var ledger = new ChangeLedger(tagsTotal, maxChanges);
        var servers = new List<SerialDeviceServer>();
        using var lineClock = new LineClock();
        MosquittoBroker? broker = null;
        ChangeSubscriber? subscriber = null;
        WorkerProcess? worker = null;
        try
        {
            // Persistence off, and a queue deep enough that the subscriber, which takes everything, loses nothing.
            broker = await MosquittoBroker.StartAsync(new MosquittoSettings { Persistence = false, MaxQueuedMessages = 1_000_000 });
            ChildProcesses.Add(broker.Process!);
            for (int i = 0; i < links; i++)
            {
                servers.Add(SerialDeviceServer.Start(new VirtualPlc(new VirtualPlcOptions { Units = [0] }), s.Baud, BitsPerCharacter, lineClock));
            }

            var tagByTopic = new Dictionary<string, int>(StringComparer.Ordinal);
            for (int l = 0; l < links; l++)
            {
                for (int t = 0; t < words.Length; t++)
                {
                    tagByTopic.Add($"{Prefix}/{LinkName(l)}/0/{TagName(words[t])}", (l * words.Length) + t);
                }
            }

            subscriber = await ChangeSubscriber.ConnectAsync(broker.Port, Prefix, ledger, tagByTopic, cancellationToken);
            worker = await WorkerProcess.StartAsync(workerAssembly, WorkerSettings(s, broker.Port, servers, words), cancellationToken);

            // Ready when every tag's first value has arrived.
            TimeSpan patience = TimeSpan.FromSeconds(30 + links);
            var clock = Stopwatch.StartNew();
            while (ledger.SeenTags < tagsTotal)
            {
                if (worker.HasExited)
                {
                    throw new InvalidOperationException($"The worker exited while starting:\n{worker.Output}");
                }

                if (clock.Elapsed > patience)
                {
                    throw new InvalidOperationException($"Only {ledger.SeenTags} of {tagsTotal} tags arrived within {patience.TotalSeconds} s. Worker:\n{worker.Output}\nBroker:\n{broker.Log}");
                }

                await Task.Delay(100, cancellationToken);
            }

            TimeSpan startup = clock.Elapsed;
            await Task.Delay(TimeSpan.FromSeconds(s.Warmup), cancellationToken);

            // The measured window: the writer's run.
            var plcs = servers.Select(x => x.Plc).ToArray();
            ProcessSample w0 = ProcessSample.Read(worker.Id) ?? throw new InvalidOperationException($"The worker has exited:\n{worker.Output}");
            ProcessSample b0 = ProcessSample.Read(broker.Process!.Id) ?? default;
            ProcessSample self0 = ProcessSample.Read(Environment.ProcessId) ?? default;
            long frames0 = servers.Sum(x => x.AnswerFrames);
            long chars0 = servers.Sum(x => x.LineCharacters);
            long overruns0 = worker.OverrunEvents;
            long skipped0 = worker.SkippedTicks;
            long warnings0 = worker.Warnings;
            int connections0 = servers.Sum(x => x.Connections);
            servers.ForEach(x => x.TakeSamples());
            long t0 = Stopwatch.GetTimestamp();

            using var sampling = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
            Task<long> rssMax = SampleRssAsync(worker.Id, sampling.Token);
            long written = await ChangeWriter.RunAsync(plcs, words, ledger, s.ChangeEvery, TimeSpan.FromSeconds(s.Seconds), cancellationToken);

            long t1 = Stopwatch.GetTimestamp();
            double elapsed = (t1 - t0) / (double)Stopwatch.Frequency;
            ProcessSample w1 = ProcessSample.Read(worker.Id) ?? throw new InvalidOperationException($"The worker has exited:\n{worker.Output}");
            ProcessSample b1 = ProcessSample.Read(broker.Process!.Id) ?? default;
            ProcessSample self1 = ProcessSample.Read(Environment.ProcessId) ?? default;
            long frames = servers.Sum(x => x.AnswerFrames) - frames0;
            long chars = servers.Sum(x => x.LineCharacters) - chars0;
            long overruns = worker.OverrunEvents - overruns0;
            long skipped = worker.SkippedTicks - skipped0;
            long warnings = worker.Warnings - warnings0;
            int reconnects = servers.Sum(x => x.Connections) - connections0;
            var pacing = servers.Select(x => x.TakeSamples()).ToArray();
            double[] gaps = pacing.SelectMany(p => p.GapsMs).Order().ToArray();
            double[] lateness = pacing.SelectMany(p => p.LatenessMs).Order().ToArray();
            double loadEnd = ProcessSample.LoadAverage();

            // Grace: what was written last is still on its way (a poll interval, then the broker).
            var grace = Stopwatch.StartNew();
            while (ledger.Missing() > 0 && grace.Elapsed < TimeSpan.FromSeconds(10) + (2 * s.Interval))
            {
                await Task.Delay(100, cancellationToken);
            }

            await sampling.CancelAsync();
            long rss = await rssMax;
            long lost = ledger.Missing();
            (double[] changeMs, double[] readMs) = ledger.Latencies();

            double tps = frames / elapsed;
            double expected = tagsTotal / s.Interval.TotalSeconds;
            double lineBusy = chars * BitsPerCharacter / (double)s.Baud / elapsed / links;
            string row = string.Create(CultureInfo.InvariantCulture,
                $"| {links} | {tagsTotal} | {tps:0.0} ({expected:0}) | {lineBusy:P1} | {Percentile(gaps, 0.50):0.0} | {w1.CpuPercentSince(w0, elapsed):0.0} | {rss / 1024.0:0} | {Percentile(changeMs, 0.50):0} / {Percentile(changeMs, 0.99):0} | {Percentile(readMs, 0.50):0} / {Percentile(readMs, 0.99):0} | {written} / {lost} | {overruns} ({skipped} ticks) | {b1.CpuPercentSince(b0, elapsed):0.0} | {self1.CpuPercentSince(self0, elapsed):0.0} | {loadStart:0.0} → {loadEnd:0.0} |");
            string note = string.Create(CultureInfo.InvariantCulture,
                $"<!-- N={links}: first values of all tags {startup.TotalSeconds:0.0} s after start; window {elapsed:0.0} s; {subscriber.Messages} messages received, {ledger.Duplicates} duplicates, {ledger.OutOfOrder} out of order, {ledger.NotGood} not good, {subscriber.Unparsed} unparsed; line pacing late by p50 {Percentile(lateness, 0.50):0.00} / p99 {Percentile(lateness, 0.99):0.00} ms, host gap p90 {Percentile(gaps, 0.90):0.0} ms; {warnings} worker warnings; {reconnects} reconnections to the device servers -->");
            if (warnings > 0)
            {
                note += Environment.NewLine + "<!-- worker warnings (last):" + Environment.NewLine + worker.WarningLines + Environment.NewLine + "-->";
            }

            return new Result(row, note);
        }
        finally
        {
            bool graceful = true;
            if (worker is not null)
            {
                graceful = await worker.StopAsync();
                await worker.DisposeAsync();
            }

            if (subscriber is not null)
            {
                await subscriber.DisposeAsync();
            }

            foreach (SerialDeviceServer server in servers)
            {
                await server.DisposeAsync();
            }

            if (broker is not null)
            {
                if (broker.Process is { } brokerProcess)
                {
                    ChildProcesses.Remove(brokerProcess);
                }

                await broker.DisposeAsync();
            }

            if (!graceful)
            {
                Console.Error.WriteLine($"scale: the worker with {links} links did not stop within 20 s of SIGTERM and was killed.");
            }
        }
    }

    private static JsonObject WorkerSettings(Settings s, int brokerPort, List<SerialDeviceServer> servers, int[] words)
    {
        var linksNode = new JsonObject();
        for (int l = 0; l < servers.Count; l++)
        {
            var groups = new JsonObject();
            foreach (int w in words)
            {
                groups[TagName(w)] = new JsonObject
                {
                    ["Unit"] = 0,
                    ["Address"] = $"D{w}",
                    ["Type"] = "word",
                    ["Interval"] = s.Interval.ToString("c", CultureInfo.InvariantCulture),
                    ["Log"] = "OnChange",
                };
            }

            linksNode[LinkName(l)] = new JsonObject
            {
                ["Tcp"] = $"127.0.0.1:{servers[l].Port}",
                ["Serial"] = new JsonObject { ["BaudRate"] = s.Baud },
                ["CommandSet"] = "CMode",

                // One RD a tag, as the figures above count them (QQ would read each link's tags with one QQIR).
                ["UseCompoundRead"] = "Off",
                ["Groups"] = groups,
            };
        }

        return new JsonObject
        {
            ["Logging"] = new JsonObject
            {
                ["LogLevel"] = new JsonObject
                {
                    ["Default"] = "Warning",
                    ["OmronHostLink"] = "Error",
                    // Debug for the overrun events (1007); values are logged on change (1001, Information).
                    ["OmronHostLink.Gateway"] = "Debug",
                },
                ["Console"] = new JsonObject
                {
                    ["FormatterName"] = "simple",
                    ["FormatterOptions"] = new JsonObject { ["SingleLine"] = true },
                },
            },
            ["HostLink"] = new JsonObject { ["Links"] = linksNode },
            ["Mqtt"] = new JsonObject
            {
                ["Host"] = "127.0.0.1",
                ["Port"] = brokerPort,
                ["ClientId"] = "scale-worker",
                ["TopicPrefix"] = Prefix,
                ["QoS"] = 1,
            },
        };
    }

    private static async Task<long> SampleRssAsync(int pid, CancellationToken cancellationToken)
    {
        long max = 0;
        // Bounded by the window (cancelled at its end) and by a count, should the cancellation never come.
        for (int i = 0; i < 100_000 && !cancellationToken.IsCancellationRequested; i++)
        {
            if (ProcessSample.Read(pid) is { } sample)
            {
                max = Math.Max(max, sample.RssKilobytes);
            }

            try
            {
                await Task.Delay(500, cancellationToken).ConfigureAwait(false);
            }
            catch (OperationCanceledException)
            {
                break;
            }
        }

        return max;
    }

    private static double Percentile(double[] sorted, double p)
        => sorted.Length == 0 ? double.NaN : sorted[Math.Clamp((int)Math.Ceiling(p * sorted.Length) - 1, 0, sorted.Length - 1)];

    private static string LinkName(int index) => $"l{index + 1:D3}";

    private static string TagName(int word) => $"d{word}";

    private readonly record struct Result(string Row, string Note);

    private sealed record Settings(int[] Links, int Seconds, int Warmup, int Tags, TimeSpan Interval, TimeSpan ChangeEvery, int Baud, string? Worker)
    {
        public static Settings Parse(string[] args)
        {
            int[] links = [1, 10, 50, 100];
            int seconds = 60;
            int warmup = 5;
            int tags = 10;
            double interval = 1;
            double changeEvery = 2;
            int baud = 9600;
            string? worker = null;
            for (int i = 0; i < args.Length; i++)
            {
                string Value() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"{args[i]} needs a value.");
                switch (args[i])
                {
                    case "--links":
                        links = Value().Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).Select(x => int.Parse(x, CultureInfo.InvariantCulture)).ToArray();
                        break;
                    case "--seconds":
                        seconds = int.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--warmup":
                        warmup = int.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--tags":
                        tags = int.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--interval":
                        interval = double.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--change-every":
                        changeEvery = double.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--baud":
                        baud = int.Parse(Value(), CultureInfo.InvariantCulture);
                        break;
                    case "--worker":
                        worker = Value();
                        break;
                    default:
                        throw new ArgumentException($"Unknown option {args[i]}.");
                }
            }

            if (links.Length == 0 || links.Any(n => n is < 1 or > 999))
            {
                throw new ArgumentException("--links takes link counts from 1 to 999, comma-separated.");
            }

            if (seconds is < 1 or > 3600 || warmup is < 0 or > 600)
            {
                throw new ArgumentException("--seconds takes 1-3600 and --warmup 0-600.");
            }

            if (tags is < 1 or > 100)
            {
                throw new ArgumentException("--tags takes 1-100 tags per link.");
            }

            if (interval is <= 0 or > 60 || changeEvery <= interval)
            {
                throw new ArgumentException("--interval takes seconds above 0 (at most 60), and --change-every must be longer than it, so that no change is legitimately coalesced with the next.");
            }

            if (baud is < 300 or > 230400)
            {
                throw new ArgumentException("--baud takes 300-230400.");
            }

            return new Settings(links, seconds, warmup, tags, TimeSpan.FromSeconds(interval), TimeSpan.FromSeconds(changeEvery), baud, worker);
        }
    }
}
