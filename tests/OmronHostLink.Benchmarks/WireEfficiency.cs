using System.Diagnostics;
using System.Globalization;
using OmronHostLink.Transports;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// <c>wire</c> mode: the client against the simulator with wire-time emulation in both directions, over the in-process
/// <see cref="InMemoryLink"/>; measured time against the least the line allows.
/// </summary>
internal static class WireEfficiency
{
    private const int Bits = 11;

    // BCD is left out: the simulator's memory holds arbitrary words, which a BCD tag would refuse.
    private static readonly PlcValueType[] TagTypes = [PlcValueType.Word, PlcValueType.Int16, PlcValueType.Int32, PlcValueType.UInt32, PlcValueType.Float, PlcValueType.Bit];

    public static async Task<int> RunAsync(string[] args)
    {
        int runs = 5;
        bool skipPlan = false;
        bool skipWire = false;
        bool skipTcp = false;
        int tcpTransactions = 301;
        var planTurnaround = TimeSpan.Zero;
        int[] bauds = [9600, 115200];
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--runs":
                    runs = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--plan-only":
                    skipWire = true;
                    skipTcp = true;
                    break;
                case "--tcp-only":
                    skipWire = true;
                    skipPlan = true;
                    break;
                case "--no-tcp":
                    skipTcp = true;
                    break;
                case "--baud":
                    bauds = [int.Parse(args[++i], CultureInfo.InvariantCulture)];
                    break;
                case "--tcp-transactions":
                    tcpTransactions = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--no-plan":
                    skipPlan = true;
                    break;
                case "--plan-turnaround":
                    // The PLC's turnaround for the planned reads: each exchange pays it once.
                    planTurnaround = TimeSpan.FromMilliseconds(int.Parse(args[++i], CultureInfo.InvariantCulture));
                    break;
            }
        }

        Console.WriteLine($"# Wire efficiency: {Environment.ProcessorCount} cores, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}, {System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}; median of {runs} runs");
        if (!skipWire)
        {
            Console.WriteLine();
            Console.WriteLine("| Line | Turnaround | Words | Frames | Chars on wire | Theoretical ms | Measured ms (median) | Min–max ms | Efficiency |");
            Console.WriteLine("|---|---|---|---|---|---|---|---|---|");
            var splits = new List<string>();
            foreach (int baud in bauds)
            {
                foreach (int turnaround in new[] { 0, 10 })
                {
                    await using var rig = await Rig.StartAsync(baud, TimeSpan.FromMilliseconds(turnaround));
                    foreach (int words in new[] { 1, 30, 100, 1000 })
                    {
                        Measurement m = await rig.MeasureAsync(runs, c => c.ReadWordsAsync("D0", words));
                        int expected = ReadPlanner.CModeReadCharacters(PlcArea.Dm, words, out int exchanges);
                        if (m.Characters != expected || m.Exchanges != exchanges)
                        {
                            Console.WriteLine($"<!-- counted {m.Characters} chars / {m.Exchanges} exchanges; formula {expected} / {exchanges} -->");
                        }

                        Console.WriteLine($"| {baud} 7E2 | {turnaround} ms | {words} | {m.Exchanges} | {m.Characters} | {m.TheoreticalMs:0.00} | {m.MedianMs:0.00} | {m.MinMs:0.00}–{m.MaxMs:0.00} | {m.Efficiency:P1} |");
                    }

                    Measurement one = await rig.MeasureAsync(runs, c => c.ReadWordsAsync("D0", 1000));
                    Measurement split = await rig.MeasureAsync(runs, async c =>
                    {
                        for (int done = 0; done < 1000; done += 30)
                        {
                            await c.ReadWordsAsync(PlcAddress.WordOf(PlcArea.Dm, done), Math.Min(30, 1000 - done));
                        }
                    });
                    splits.Add($"| {baud} 7E2 | {turnaround} ms | {one.MedianMs:0} ms (1 command, {one.Exchanges} frames) | {split.MedianMs:0} ms (34 commands) | {split.MedianMs / one.MedianMs:0.00}× | {split.Characters} vs {one.Characters} |");
                }
            }

            double rd30 = (17 + 131) * 11 / 9600.0 * 1000;
            Console.WriteLine();
            Console.WriteLine($"30-word RD at 9600 7E2, turnaround 0: theoretical (17 + 131) × 11 / 9600 s = {rd30:0.00} ms (see the 9600 / 0 ms / 30 row).");
            Console.WriteLine();
            Console.WriteLine("## 1000 words: one multi-frame transaction vs. 30-word commands");
            Console.WriteLine();
            Console.WriteLine("| Line | Turnaround | One transaction | Split into 30-word RDs | Split / one | Characters (split vs one) |");
            Console.WriteLine("|---|---|---|---|---|---|");
            splits.ForEach(Console.WriteLine);
        }

        if (!skipTcp)
        {
            await MinimalClientComparison.RunAsync(tcpTransactions);
        }

        if (!skipPlan)
        {
            await PlanAsync(runs, planTurnaround);
        }

        return 0;
    }

    private static async Task PlanAsync(int runs, TimeSpan turnaround)
    {
        Console.WriteLine();
        Console.WriteLine($"## 100 scattered tags (seed 42, units 0 and 1), 9600 7E2, turnaround {turnaround.TotalMilliseconds:0} ms");
        Console.WriteLine();
        Console.WriteLine("| Protocol | Method | Transactions | Chars on wire | Measured ms (median) | Speed-up |");
        Console.WriteLine("|---|---|---|---|---|---|");
        PlcTag[] tags = ScatteredTags(100, 42);
        var qqRows = new List<string>();
        foreach (HostLinkCommandSet protocol in new[] { HostLinkCommandSet.CMode, HostLinkCommandSet.Fins })
        {
            await using var rig = await Rig.StartAsync(9600, turnaround, protocol);
            ReadPlan plan = new ReadPlanner(protocol, new LineTiming(9600, Bits)) { UseCompoundRead = CompoundReadMode.Off }.Plan(tags);
            Measurement planned = await rig.MeasureAsync(runs, c => c.ReadTagsAsync(plan));
            Measurement naive = await rig.MeasureAsync(runs, async c =>
            {
                foreach (PlcTag tag in tags)
                {
                    HostLinkUnit unit = tag.Unit is { } u ? c.Unit(u) : c;
                    await unit.ReadWordsAsync(tag.Address.AsWord(), tag.WordCount);
                }
            });
            string name = protocol == HostLinkCommandSet.CMode ? "C-mode" : "FINS";
            Console.WriteLine($"| {name} | one read per tag | {naive.Exchanges} | {naive.Characters} | {naive.MedianMs:0} | 1.00× |");
            Console.WriteLine($"| {name} | ReadTagsAsync (planned: {Kinds(plan)}) | {plan.TransactionCount} | {planned.Characters} | {planned.MedianMs:0} | {naive.MedianMs / planned.MedianMs:0.00}× |");
            if (protocol != HostLinkCommandSet.CMode)
            {
                continue;
            }

            // QQ: the same tags with the compound read; the registration is paid by the first run (and the warm-up
            // below), so the median is a cycle of QQIRs and the area reads QQ does not cover.
            ReadPlan qq = new ReadPlanner(protocol, new LineTiming(9600, Bits)) { UseCompoundRead = CompoundReadMode.On }.Plan(tags);
            await rig.Client.ReadTagsAsync(qq);
            Measurement compound = await rig.MeasureAsync(runs, c => c.ReadTagsAsync(qq));
            Console.WriteLine($"| {name} | ReadTagsAsync with QQ (planned: {Kinds(qq)}) | {qq.TransactionCount} | {compound.Characters} | {compound.MedianMs:0} | {naive.MedianMs / compound.MedianMs:0.00}× |");
            qqRows.Add($"| ReadTagsAsync, 57-read plan | {planned.Characters} | {planned.TheoreticalMs:0} | {planned.MedianMs:0} | {planned.Efficiency:P1} | 1.00× |");
            qqRows.Add($"| ReadTagsAsync with QQ | {compound.Characters} | {compound.TheoreticalMs:0} | {compound.MedianMs:0} | {compound.Efficiency:P1} | {planned.MedianMs / compound.MedianMs:0.00}× |");

            Measurement watch = await rig.MeasureWatchAsync(Math.Max(runs, 5), tags);
            qqRows.Add($"| WatchAsync cycle with QQ (median of {Math.Max(runs, 5)} cycles after the first) | {watch.Characters} | {watch.TheoreticalMs:0} | {watch.MedianMs:0} | {watch.Efficiency:P1} | {planned.MedianMs / watch.MedianMs:0.00}× |");
        }

        Console.WriteLine();
        Console.WriteLine($"## C-mode with QQ: 100 scattered tags, 9600 7E2, turnaround {turnaround.TotalMilliseconds:0} ms (theoretical = characters on the wire × 11 / 9600 + a turnaround an exchange)");
        Console.WriteLine();
        Console.WriteLine("| Read | Chars on wire | Theoretical ms | Measured ms (median) | Efficiency | Faster than the 57-read plan |");
        Console.WriteLine("|---|---|---|---|---|---|");
        qqRows.ForEach(Console.WriteLine);
    }

    private static string Kinds(ReadPlan plan) => string.Join(", ", plan.Reads.GroupBy(r => r.Kind).Select(g => $"{g.Count()} {g.Key}"));

    /// <summary>Clusters of tags around hot spots plus loners, in D, H, CIO, A, EM bank 1 and timers, two units, some overlapping.</summary>
    internal static PlcTag[] ScatteredTags(int count, int seed)
    {
        var random = new Random(seed);
        string[] areas = ["D", "D", "D", "H", "CIO", "A", "E1_", "T"];
        var spots = Enumerable.Range(0, 12).Select(_ => (Area: areas[random.Next(areas.Length)], Word: random.Next(0, 400) * 5)).ToArray();
        var tags = new List<PlcTag>();
        while (tags.Count < count)
        {
            (string area, int word) = random.Next(4) == 0
                ? (areas[random.Next(areas.Length)], random.Next(0, 2000))
                : spots[random.Next(spots.Length)] is var s ? (s.Area, s.Word + random.Next(0, 40)) : default;
            int max = area switch { "H" => 510, "A" => 958, "T" => 2046, _ => 9998 };
            word = Math.Min(word, max);
            PlcValueType type = area == "T" ? PlcValueType.Word : TagTypes[random.Next(TagTypes.Length)];
            string address = type == PlcValueType.Bit ? $"{area}{word}.{random.Next(16):D2}" : $"{area}{word}";
            tags.Add(new PlcTag(address, type, random.Next(10) < 3 ? 1 : null));
        }

        return tags.ToArray();
    }

    private readonly record struct Measurement(double MedianMs, double MinMs, double MaxMs, int Characters, int Exchanges, double TheoreticalMs)
    {
        public double Efficiency => TheoreticalMs / MedianMs;
    }

    private sealed class Rig : IAsyncDisposable
    {
        private readonly CancellationTokenSource _stop = new();
        private PacedLineStream _line = null!;
        private Task _session = Task.CompletedTask;
        private HostLinkClient _client = null!;
        private int _baud;
        private TimeSpan _turnaround;

        public static async Task<Rig> StartAsync(int baud, TimeSpan turnaround, HostLinkCommandSet protocol = HostLinkCommandSet.CMode)
        {
            var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0, 1], BaudRate = baud, BitsPerCharacter = Bits, Turnaround = turnaround });
            for (int i = 0; i < 10000; i++)
            {
                plc.WriteWord(PlcArea.Dm, i, (ushort)(i * 3));
            }

            (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
            var rig = new Rig { _baud = baud, _turnaround = turnaround };
            rig._session = plc.RunAsync(plcEnd, rig._stop.Token);
            rig._line = new PacedLineStream(host, baud, Bits);
            rig._client = HostLinkClient.ForStream(rig._line, new HostLinkClientOptions
            {
                LineTiming = new LineTiming(baud, Bits),
                TurnaroundAllowance = TimeSpan.FromMilliseconds(200) + turnaround,
                CommandSet = protocol,
                UseCompoundRead = CompoundReadMode.On,
            });

            // Warm-up: JIT, pools, the link's pump.
            for (int i = 0; i < 3; i++)
            {
                await rig._client.ReadWordsAsync("D0", 31);
            }

            return rig;
        }

        public HostLinkClient Client => _client;

        /// <summary>The time and characters of one WatchAsync cycle: the median over <paramref name="cycles"/> cycles after the first (which registers).</summary>
        public async Task<Measurement> MeasureWatchAsync(int cycles, IReadOnlyList<PlcTag> tags)
        {
            var times = new List<double>();
            int chars = 0;
            int exchanges = 0;
            long start = 0;
            int seen = 0;
            await foreach (WatchEvent e in _client.WatchAsync(tags, new WatchOptions { Interval = TimeSpan.Zero, ReportEveryCycle = true }))
            {
                if (e.Kind != WatchEventKind.Polled)
                {
                    continue;
                }

                if (seen > 0)
                {
                    times.Add((Stopwatch.GetTimestamp() - start) * 1000.0 / Stopwatch.Frequency);
                    chars = (int)(_line.Sent + _line.Received);
                    exchanges = _line.Writes;
                }

                if (++seen > cycles)
                {
                    break;
                }

                _line.ResetCounters();
                start = Stopwatch.GetTimestamp();
            }

            times.Sort();
            double theoretical = (chars * Bits * 1000.0 / _baud) + (exchanges * _turnaround.TotalMilliseconds);
            return new Measurement(times[times.Count / 2], times[0], times[^1], chars, exchanges, theoretical);
        }

        public async Task<Measurement> MeasureAsync(int runs, Func<HostLinkClient, Task> action)
        {
            var times = new List<double>();
            int chars = 0;
            int exchanges = 0;
            for (int r = 0; r < runs; r++)
            {
                _line.ResetCounters();
                long start = Stopwatch.GetTimestamp();
                await action(_client);
                times.Add((Stopwatch.GetTimestamp() - start) * 1000.0 / Stopwatch.Frequency);
                chars = (int)(_line.Sent + _line.Received);
                exchanges = _line.Writes;
            }

            times.Sort();
            double theoretical = (chars * Bits * 1000.0 / _baud) + (exchanges * _turnaround.TotalMilliseconds);
            return new Measurement(times[times.Count / 2], times[0], times[^1], chars, exchanges, theoretical);
        }

        public async ValueTask DisposeAsync()
        {
            await _client.DisposeAsync();
            await _stop.CancelAsync();
            await _session;
            _stop.Dispose();
        }
    }
}
