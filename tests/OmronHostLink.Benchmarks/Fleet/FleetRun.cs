using System.Diagnostics;
using System.Globalization;
using System.Net;
using System.Net.Sockets;
using System.Runtime.InteropServices;
using System.Text.Json;
using System.Text.Json.Nodes;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Gateway.Sparkplug.Wire;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Fleet;

/// <summary>
/// <c>fleet</c> mode: a plant's gateways against two brokers. G gateway processes, each with L links to simulated PLCs
/// (a <see cref="VirtualPlc"/> on its own loopback port each), both outputs on — the MQTT JSON output and a Sparkplug B
/// edge node — each with the server list [A, B] and its durable store. A writer changes every PLC's counter D0 on a
/// fixed schedule; consumers on both brokers record every message. Mid-run broker A is killed with SIGKILL: every
/// output must be on B within 2 × keep-alive, and every change a gateway read (its log says which) must reach a consumer
/// — JSON and Sparkplug each — live or as history. The brokers share one log file, which shows no client id connected
/// to both at once. Reports, per gateway, CPU and resident memory.
/// </summary>
internal static class FleetRun
{
    private const string Group = "Fleet";

    public static async Task<int> RunAsync(string[] args)
    {
        Settings s;
        try
        {
            s = Settings.Parse(args);
        }
        catch (Exception e) when (e is FormatException or ArgumentException)
        {
            Console.Error.WriteLine($"fleet: {e.Message}");
            Console.Error.WriteLine("usage: fleet [--gateways 20] [--links 5] [--seconds 60] [--kill-at 30] [--warmup 30] [--change-every 1s] [--poll 250ms] [--keep-alive 15s] [--worker path/OmronHostLink.Gateway.dll]");
            return 2;
        }

        using var stop = new CancellationTokenSource();
        Console.CancelKeyPress += (_, e) =>
        {
            e.Cancel = true;
            stop.Cancel();
        };

        string worker = WorkerProcess.Locate(s.Worker);
        Console.WriteLine($"# Fleet: {s.Gateways} gateways x {s.Links} links against brokers A and B. {Environment.ProcessorCount} cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.FrameworkDescription}, {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC; load average {ProcessSample.LoadAverage():0.0}");
        Console.WriteLine($"# each link: one counter (D0) polled every {s.Poll.TotalMilliseconds:0} ms, changed every {s.ChangeEvery.TotalMilliseconds:0} ms; both outputs with Servers [A, B], keep-alive {s.KeepAlive.TotalSeconds:0} s, durable stores; A killed (SIGKILL) {s.KillAt} s into {s.Seconds} s measured after {s.Warmup} s warm-up");
        try
        {
            return await RunOnceAsync(s, worker, stop.Token);
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            Console.Error.WriteLine("fleet: stopped; children ended.");
            return 130;
        }
    }

    private static async Task<int> RunOnceAsync(Settings s, string worker, CancellationToken cancellationToken)
    {
        string work = Directory.CreateTempSubdirectory("ohl-fleet-").FullName;
        string sharedLog = Path.Combine(work, "brokers.log");
        var clock = Stopwatch.StartNew();
        await using MosquittoBroker a = await MosquittoBroker.StartAsync(new MosquittoSettings { SharedLogFile = sharedLog, LogTag = "A", MaxQueuedMessages = 1_000_000, Persistence = false });
        await using MosquittoBroker b = await MosquittoBroker.StartAsync(new MosquittoSettings { SharedLogFile = sharedLog, LogTag = "B", MaxQueuedMessages = 1_000_000, Persistence = false });
        ChildProcesses.Add(a.Process!);
        ChildProcesses.Add(b.Process!);

        // The PLCs: one per link, each on its own port.
        using var plcsStop = new CancellationTokenSource();
        var plcs = new List<(string Gateway, string Link, VirtualPlc Plc, TcpListener Listener, Task Accepting)>();
        for (int g = 0; g < s.Gateways; g++)
        {
            for (int l = 0; l < s.Links; l++)
            {
                var plc = new VirtualPlc();
                var listener = new TcpListener(IPAddress.Loopback, 0);
                listener.Start();
                plcs.Add((GatewayName(g), LinkName(l), plc, listener, AcceptAsync(listener, plc, plcsStop.Token)));
            }
        }

        string[] filters = ["fleet/#", $"spBv1.0/{Group}/#"];
        await using FleetRecorder onA = await FleetRecorder.ConnectAsync(a.Port, "A", filters, clock, cancellationToken);
        await using FleetRecorder onB = await FleetRecorder.ConnectAsync(b.Port, "B", filters, clock, cancellationToken);

        var gateways = new List<FleetGateway>();
        try
        {
            for (int g = 0; g < s.Gateways; g++)
            {
                string name = GatewayName(g);
                gateways.Add(await FleetGateway.StartAsync(worker, name, GatewaySettings(s, name, a.Port, b.Port, plcs.Where(p => p.Gateway == name).Select(p => (p.Link, ((IPEndPoint)p.Listener.LocalEndpoint).Port)), Path.Combine(work, name)), cancellationToken));
            }

            // Started (on a loaded machine that may take minutes): every gateway's two outputs are on A.
            var starting = Stopwatch.StartNew();
            while (!gateways.All(gw => onA.Messages.Any(m => m.Topic == $"spBv1.0/{Group}/NBIRTH/{gw.Name}") && onA.Messages.Any(m => m.Topic == $"fleet/{gw.Name}/status/{gw.Name}")))
            {
                if (starting.Elapsed > TimeSpan.FromMinutes(15))
                {
                    throw new InvalidOperationException("The gateways did not all connect to broker A within 15 minutes.");
                }

                await Task.Delay(TimeSpan.FromSeconds(1), cancellationToken);
            }

            Console.WriteLine($"# {clock.Elapsed.TotalSeconds:0} s: every gateway on A ({starting.Elapsed.TotalSeconds:0} s to start {s.Gateways} processes); load average {ProcessSample.LoadAverage():0.0}");

            // The writer: every counter one more, on a fixed schedule.
            using var writing = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
            int written = 0;
            Task writer = Task.Run(async () =>
            {
                using var timer = new PeriodicTimer(s.ChangeEvery);
                try
                {
                    while (await timer.WaitForNextTickAsync(writing.Token))
                    {
                        ushort next = (ushort)Interlocked.Increment(ref written);
                        foreach (var p in plcs)
                        {
                            p.Plc.WriteWords("D0", [next]);
                        }
                    }
                }
                catch (OperationCanceledException)
                {
                }
            });

            await Task.Delay(TimeSpan.FromSeconds(s.Warmup), cancellationToken);
            TimeSpan measureStart = clock.Elapsed;
            ProcessSample?[] cpuStart = gateways.Select(gw => ProcessSample.Read(gw.Id)).ToArray();
            long[] rssMax = new long[gateways.Count];
            using var sampling = new CancellationTokenSource();
            Task sampler = Task.Run(async () =>
            {
                while (!sampling.IsCancellationRequested)
                {
                    for (int i = 0; i < gateways.Count; i++)
                    {
                        if (ProcessSample.Read(gateways[i].Id) is { } sample)
                        {
                            rssMax[i] = Math.Max(rssMax[i], sample.RssKilobytes);
                        }
                    }

                    try
                    {
                        await Task.Delay(TimeSpan.FromSeconds(1), sampling.Token);
                    }
                    catch (OperationCanceledException)
                    {
                    }
                }
            });

            Console.WriteLine($"# {clock.Elapsed.TotalSeconds:0} s: measuring; {CountOn(onA.Messages, "NBIRTH")} NBIRTH on A so far");
            await Task.Delay(TimeSpan.FromSeconds(s.KillAt), cancellationToken);
            ConnectionTimelineMarker(sharedLog, "A");
            TimeSpan killedAt = clock.Elapsed;
            await a.KillAsync();
            Console.WriteLine($"# {killedAt.TotalSeconds:0.0} s: broker A killed (SIGKILL); load average {ProcessSample.LoadAverage():0.0}");

            await Task.Delay(TimeSpan.FromSeconds(s.Seconds - s.KillAt), cancellationToken);
            TimeSpan measureEnd = clock.Elapsed;
            ProcessSample?[] cpuEnd = gateways.Select(gw => ProcessSample.Read(gw.Id)).ToArray();
            await sampling.CancelAsync();
            await sampler;
            await writing.CancelAsync();
            await writer;
            Console.WriteLine($"# {clock.Elapsed.TotalSeconds:0} s: writer stopped after {written} changes; waiting for every output to drain");

            // Drained: every gateway's last reading arrived on B through both outputs, and their stores are empty.
            var drainClock = Stopwatch.StartNew();
            Analysis analysis;
            while (true)
            {
                analysis = Analyse(gateways, onA.Messages, onB.Messages, killedAt);
                if (analysis.Drained || drainClock.Elapsed > TimeSpan.FromSeconds(180))
                {
                    break;
                }

                await Task.Delay(TimeSpan.FromSeconds(2), cancellationToken);
            }

            Console.WriteLine($"# drained: {analysis.Drained} after {drainClock.Elapsed.TotalSeconds:0} s");
            foreach (FleetGateway gateway in gateways)
            {
                await gateway.StopAsync();
            }

            // Report.
            double seconds = (measureEnd - measureStart).TotalSeconds;
            double[] cpu = cpuStart.Zip(cpuEnd, (x, y) => x is { } s0 && y is { } s1 ? s1.CpuPercentSince(s0, seconds) : double.NaN).ToArray();
            Console.WriteLine();
            Console.WriteLine("| Gateway | CPU % of a core | RSS max MB | JSON on B after kill (s) | Sparkplug NBIRTH on B after kill (s) | Changes read | JSON lost / duplicates | Sparkplug lost / duplicates / as history | Warnings |");
            Console.WriteLine("|---|---|---|---|---|---|---|---|---|");
            for (int i = 0; i < gateways.Count; i++)
            {
                GatewayResult r = analysis.Gateways[i];
                Console.WriteLine($"| {gateways[i].Name} | {cpu[i]:0.0} | {rssMax[i] / 1024.0:0} | {Seconds(r.JsonOnB)} | {Seconds(r.NodeOnB)} | {r.Read} | {r.JsonLost} / {r.JsonDuplicates} | {r.SparkplugLost} / {r.SparkplugDuplicates} / {r.SparkplugHistorical} | {gateways[i].Warnings} |");
            }

            double bound = 2 * s.KeepAlive.TotalSeconds;
            (IReadOnlyList<string> overlaps, int clients) = Overlaps(sharedLog, gateways.SelectMany(g => new[] { g.Name, $"{Group}-{g.Name}" }));
            Console.WriteLine();
            Console.WriteLine($"- CPU % of a core per gateway: mean {cpu.Average():0.0}, max {cpu.Max():0.0}; RSS max MB: mean {rssMax.Average() / 1024.0:0}, max {rssMax.Max() / 1024.0:0}");
            Console.WriteLine($"- on B after the kill (bound 2 x keep-alive = {bound:0} s): JSON max {analysis.Gateways.Max(r => r.JsonOnB ?? double.PositiveInfinity):0.00} s, Sparkplug max {analysis.Gateways.Max(r => r.NodeOnB ?? double.PositiveInfinity):0.00} s; all within: {analysis.Gateways.All(r => r.JsonOnB <= bound && r.NodeOnB <= bound)}");
            Console.WriteLine($"- changes read {analysis.Gateways.Sum(r => r.Read)}; lost JSON {analysis.Gateways.Sum(r => r.JsonLost)}, Sparkplug {analysis.Gateways.Sum(r => r.SparkplugLost)}; duplicates JSON {analysis.Gateways.Sum(r => r.JsonDuplicates)}, Sparkplug {analysis.Gateways.Sum(r => r.SparkplugDuplicates)}; Sparkplug as history {analysis.Gateways.Sum(r => r.SparkplugHistorical)}");
            Console.WriteLine($"- messages: on A {onA.Messages.Count}, on B {onB.Messages.Count}; {clients} client ids, connected to two brokers at once: {overlaps.Count}; load average at the end {ProcessSample.LoadAverage():0.0}");
            foreach (string overlap in overlaps.Take(10))
            {
                Console.WriteLine("  overlap: " + overlap);
            }

            foreach (FleetGateway gateway in gateways.Where(g => g.Warnings > 0).Take(3))
            {
                Console.WriteLine($"- warnings of {gateway.Name}:{Environment.NewLine}{gateway.WarningLines}");
            }

            return 0;
        }
        finally
        {
            foreach (FleetGateway gateway in gateways)
            {
                await gateway.DisposeAsync();
            }

            await plcsStop.CancelAsync();
            foreach (var p in plcs)
            {
                p.Listener.Stop();
                await p.Accepting.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
            }
        }
    }

    private static string Seconds(double? value) => value is { } v ? v.ToString("0.00", CultureInfo.InvariantCulture) : "never";

    private static string GatewayName(int g) => $"g{g:00}";

    private static string LinkName(int l) => $"l{l}";

    private static void ConnectionTimelineMarker(string file, string tag) => File.AppendAllText(file, $"{tag}:0: killed by the test{Environment.NewLine}");

    private static int CountOn(IReadOnlyList<FleetMessage> messages, string type) => messages.Count(m => m.Topic.Contains("/" + type + "/", StringComparison.Ordinal));

    private static async Task AcceptAsync(TcpListener listener, VirtualPlc plc, CancellationToken cancellationToken)
    {
        var sessions = new List<Task>();
        try
        {
            while (!cancellationToken.IsCancellationRequested)
            {
                TcpClient client = await listener.AcceptTcpClientAsync(cancellationToken);
                client.NoDelay = true;
                sessions.Add(Task.Run(async () =>
                {
                    using (client)
                    {
                        await plc.RunAsync(client.GetStream(), cancellationToken).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
                    }
                }, CancellationToken.None));
            }
        }
        catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
        {
        }

        await Task.WhenAll(sessions).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
    }

    private static JsonObject GatewaySettings(Settings s, string name, int portA, int portB, IEnumerable<(string Link, int Port)> links, string state)
    {
        var linksNode = new JsonObject();
        foreach ((string link, int port) in links)
        {
            linksNode[link] = new JsonObject
            {
                ["Tcp"] = $"127.0.0.1:{port}",
                ["TurnaroundAllowance"] = "500ms",
                ["Groups"] = new JsonObject
                {
                    ["counter"] = new JsonObject { ["Address"] = "D0", ["Type"] = "uint16", ["Interval"] = $"{s.Poll.TotalMilliseconds}ms", ["Log"] = "OnChange" },
                },
            };
        }

        JsonArray Servers() =>
        [
            new JsonObject { ["Host"] = "127.0.0.1", ["Port"] = portA },
            new JsonObject { ["Host"] = "127.0.0.1", ["Port"] = portB },
        ];

        return new JsonObject
        {
            ["Logging"] = new JsonObject
            {
                ["LogLevel"] = new JsonObject
                {
                    ["Default"] = "Warning",
                    ["OmronHostLink"] = "Error",
                    ["OmronHostLink.Gateway"] = "Information",
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
                ["Servers"] = Servers(),
                ["ClientId"] = name,
                ["TopicPrefix"] = "fleet/" + name,
                ["KeepAlive"] = $"{s.KeepAlive.TotalSeconds}s",
                ["StatisticsInterval"] = "2s",
                ["StateDirectory"] = state,
                ["DurableQueue"] = new JsonObject { ["Enabled"] = true },
            },
            ["Sparkplug"] = new JsonObject
            {
                ["Servers"] = Servers(),
                ["GroupId"] = Group,
                ["EdgeNodeId"] = name,
                ["KeepAlive"] = $"{s.KeepAlive.TotalSeconds}s",
                ["StateDirectory"] = state,
                ["StoreAndForward"] = new JsonObject { ["Durable"] = true },
            },
        };
    }

    /// <summary>What the consumers received, against what each gateway read.</summary>
    private static Analysis Analyse(List<FleetGateway> gateways, IReadOnlyList<FleetMessage> onA, IReadOnlyList<FleetMessage> onB, TimeSpan killedAt)
    {
        FleetMessage[] all = [.. onA, .. onB];
        var results = new List<GatewayResult>();
        bool drained = true;
        foreach (FleetGateway gateway in gateways)
        {
            string name = gateway.Name;
            IReadOnlyDictionary<string, int[]> read = gateway.Read();
            var json = new Dictionary<string, List<int>>(StringComparer.Ordinal);
            var sparkplug = new Dictionary<string, List<int>>(StringComparer.Ordinal);
            int historical = 0;
            long stored = -1;
            foreach (FleetMessage m in all)
            {
                if (m.Topic.StartsWith($"fleet/{name}/", StringComparison.Ordinal))
                {
                    string[] levels = m.Topic.Split('/');
                    if (levels.Length == 5 && levels[4] == "counter")
                    {
                        using JsonDocument d = JsonDocument.Parse(m.Payload);
                        if (d.RootElement.GetProperty("quality").GetString() == "good")
                        {
                            Add(json, levels[2], d.RootElement.GetProperty("value").GetInt32());
                        }
                    }
                    else if (m.Topic == $"fleet/{name}/status/{name}/outputs" && m.Broker == "B")
                    {
                        using JsonDocument d = JsonDocument.Parse(m.Payload);
                        foreach (JsonElement o in d.RootElement.GetProperty("outputs").EnumerateArray())
                        {
                            JsonElement figures = o.GetProperty("figures");
                            if (o.GetProperty("output").GetString() == "sparkplug")
                            {
                                stored = figures.GetProperty("stored").GetInt64();
                            }
                        }
                    }
                }
                else if (m.Topic.StartsWith($"spBv1.0/{Group}/", StringComparison.Ordinal))
                {
                    string[] levels = m.Topic.Split('/');
                    if (levels.Length == 5 && levels[3] == name && levels[2] is "DBIRTH" or "DDATA")
                    {
                        foreach (Payload.Types.Metric metric in Payload.Parser.ParseFrom(m.Payload).Metrics)
                        {
                            if (!metric.IsNull && (metric.Properties is null || metric.Properties.Keys.Count == 0))
                            {
                                Add(sparkplug, levels[4][..levels[4].LastIndexOf('-')], (int)metric.IntValue);
                                historical += metric.IsHistorical ? 1 : 0;
                            }
                        }
                    }
                }
            }

            double? after(string prefix, Func<FleetMessage, bool> match) => onB.FirstOrDefault(m => m.At > killedAt && m.Topic.StartsWith(prefix, StringComparison.Ordinal) && match(m)) is { } first ? (first.At - killedAt).TotalSeconds : null;
            double? jsonOnB = after($"fleet/{name}/status/{name}", m => System.Text.Encoding.UTF8.GetString(m.Payload) == "online");
            double? nodeOnB = after($"spBv1.0/{Group}/NBIRTH/{name}", _ => true);
            int readCount = 0, jsonLost = 0, jsonDuplicates = 0, sparkplugLost = 0, sparkplugDuplicates = 0;
            foreach ((string link, int[] values) in read)
            {
                readCount += values.Length;
                List<int> j = json.GetValueOrDefault(link, []);
                List<int> sp = sparkplug.GetValueOrDefault(link, []);
                jsonLost += values.Count(v => !j.Contains(v));
                sparkplugLost += values.Count(v => !sp.Contains(v));
                jsonDuplicates += j.Count - j.Distinct().Count();
                sparkplugDuplicates += sp.Count - sp.Distinct().Count();
                drained &= values.Length > 0 && j.Contains(values[^1]) && sp.Contains(values[^1]);
            }

            // The JSON figure counts the statistics queued beside it: the last values arriving say the queue has drained.
            drained &= stored == 0;
            results.Add(new GatewayResult(readCount, jsonLost, jsonDuplicates, sparkplugLost, sparkplugDuplicates, historical, jsonOnB, nodeOnB));
        }

        return new Analysis(results, drained);
    }

    private static void Add(Dictionary<string, List<int>> values, string link, int value)
    {
        if (!values.TryGetValue(link, out List<int>? list))
        {
            values[link] = list = [];
        }

        list.Add(value);
    }

    /// <summary>The moments a client id was connected to both brokers, from their shared log.</summary>
    private static (IReadOnlyList<string> Overlaps, int Clients) Overlaps(string file, IEnumerable<string> clientIds)
    {
        var wanted = new HashSet<string>(clientIds, StringComparer.Ordinal);
        var connectedTo = new Dictionary<string, HashSet<string>>(StringComparer.Ordinal);
        var overlaps = new List<string>();
        foreach (string line in File.ReadLines(file))
        {
            int first = line.IndexOf(':', StringComparison.Ordinal);
            int second = first < 0 ? -1 : line.IndexOf(": ", first + 1, StringComparison.Ordinal);
            if (second < 0)
            {
                continue;
            }

            string tag = line[..first];
            string text = line[(second + 2)..];
            if (text == "killed by the test" || (text.StartsWith("mosquitto version", StringComparison.Ordinal) && text.EndsWith("terminating", StringComparison.Ordinal)))
            {
                foreach (HashSet<string> set in connectedTo.Values)
                {
                    set.Remove(tag);
                }
            }
            else if (text.StartsWith("New client connected from ", StringComparison.Ordinal))
            {
                string id = text.Split(" as ")[1].Split(' ')[0];
                if (wanted.Contains(id))
                {
                    if (!connectedTo.TryGetValue(id, out HashSet<string>? set))
                    {
                        connectedTo[id] = set = [];
                    }

                    set.Add(tag);
                    if (set.Count > 1)
                    {
                        overlaps.Add(line);
                    }
                }
            }
            else if (text.StartsWith("Client ", StringComparison.Ordinal) || text.StartsWith("Socket error on client ", StringComparison.Ordinal))
            {
                string id = text.StartsWith("Client ", StringComparison.Ordinal) ? text["Client ".Length..].Split(' ')[0] : text["Socket error on client ".Length..].Split(',')[0];
                if (connectedTo.TryGetValue(id, out HashSet<string>? set) && (text.Contains("disconnect", StringComparison.Ordinal) || text.Contains("closed its connection", StringComparison.Ordinal) || text.Contains("already connected", StringComparison.Ordinal) || text.Contains("exceeded timeout", StringComparison.Ordinal)))
                {
                    set.Remove(tag);
                }
            }
        }

        return (overlaps, connectedTo.Count);
    }

    private sealed record GatewayResult(int Read, int JsonLost, int JsonDuplicates, int SparkplugLost, int SparkplugDuplicates, int SparkplugHistorical, double? JsonOnB, double? NodeOnB);

    private sealed record Analysis(IReadOnlyList<GatewayResult> Gateways, bool Drained);

    private sealed record Settings(int Gateways, int Links, int Seconds, int KillAt, int Warmup, TimeSpan ChangeEvery, TimeSpan Poll, TimeSpan KeepAlive, string? Worker)
    {
        public static Settings Parse(string[] args)
        {
            var s = new Settings(20, 5, 60, 30, 30, TimeSpan.FromSeconds(1), TimeSpan.FromMilliseconds(250), TimeSpan.FromSeconds(15), null);
            for (int i = 0; i < args.Length; i++)
            {
                string value = i + 1 < args.Length ? args[i + 1] : throw new ArgumentException($"{args[i]} needs a value");
                s = args[i] switch
                {
                    "--gateways" => s with { Gateways = int.Parse(value, CultureInfo.InvariantCulture) },
                    "--links" => s with { Links = int.Parse(value, CultureInfo.InvariantCulture) },
                    "--seconds" => s with { Seconds = int.Parse(value, CultureInfo.InvariantCulture) },
                    "--kill-at" => s with { KillAt = int.Parse(value, CultureInfo.InvariantCulture) },
                    "--warmup" => s with { Warmup = int.Parse(value, CultureInfo.InvariantCulture) },
                    "--change-every" => s with { ChangeEvery = ParseDuration(value) },
                    "--poll" => s with { Poll = ParseDuration(value) },
                    "--keep-alive" => s with { KeepAlive = ParseDuration(value) },
                    "--worker" => s with { Worker = value },
                    _ => throw new ArgumentException($"unknown option {args[i]}"),
                };
                i++;
            }

            return s.KillAt < s.Seconds ? s : throw new ArgumentException("--kill-at must be less than --seconds");
        }

        private static TimeSpan ParseDuration(string text)
            => Duration.TryParse(text, out TimeSpan value, out string? error) ? value : throw new FormatException(error);
    }
}
