using System.Collections.Concurrent;
using System.Diagnostics;
using System.Globalization;
using System.Net;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;
using Xunit.Abstractions;

namespace OmronHostLink.Tests.Reliability;

/// <summary>
/// The soak: many transactions, mixed reads and writes, several units, concurrent callers on several links, against the
/// simulator injecting about 5% of each fault (drop, corrupt, noise, truncate, late answer).
/// </summary>
/// <remarks>
/// <para>Checkability under concurrent writers: every caller owns its own words (a DM block and an HR block) and keeps a
/// model of them: for each word the set of values it may hold. A write reported successful makes the set exactly
/// {value}; a failed write may or may not have been executed, so its value joins the set; a successful read must return,
/// for every word, a member of the set, and then the set collapses to what was read. A stale answer, an answer for
/// another caller's block, or a damaged value accepted as good shows up as a value outside the set.</para>
/// <para>Deadline bound of one call: the link gives each frame it waits for at most
/// <c>D = (chars sent + longest answer) × bits/baud + TurnaroundAllowance</c> with both frames at most 131 characters,
/// so <c>D ≤ WireTime(262) + TurnaroundAllowance</c>. One attempt waits for at most one TS fence (resynchronisation) and
/// one frame per command frame of a write (the last one's wait is the answer) or per answer frame of a read:
/// <c>attempt ≤ (1 + frames) × D</c>. A call makes at most <c>retries + 1</c> attempts, and with
/// <c>CallersPerLink</c> callers sharing a link it may wait for one attempt of each other caller before each of its
/// own (the link's gate releases between attempts): <c>bound = CallersPerLink × (retries + 1) × (1 + frames) × D + slack</c>.</para>
/// <para>Size: <c>HOSTLINK_SOAK_TRANSACTIONS</c> (CI default 8,000, about 20 s here; the full run is 20,000) transactions, stopped early after
/// <c>HOSTLINK_SOAK_SECONDS</c> (default 60) so that CI stays bounded; the figures are printed either way.</para>
/// </remarks>
[Collection(SoakCollection.Name)]
public sealed class SoakTests(ITestOutputHelper output)
{
    private const int Links = 8;
    private const int CallersPerLink = 2;
    private const int DmWords = 64;
    private const int HrWords = 16;
    private const double FaultRate = 0.05;
    private static readonly int[] Units = { 0, 5, 31 };
    private static readonly TimeSpan Allowance = TimeSpan.FromMilliseconds(40);
    private static readonly TimeSpan LateBy = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan Slack = TimeSpan.FromMilliseconds(250);
    private static readonly LineTiming Timing = new(1_000_000, 11);

    [Fact]
    [Trait("Category", "Slow")]
    public async Task Soak_with_faults_returns_no_wrong_value_types_every_failure_and_recovers()
    {
        await using var stalls = new RuntimeStalls();
        int target = EnvInt("HOSTLINK_SOAK_TRANSACTIONS", 8_000);
        TimeSpan budget = TimeSpan.FromSeconds(EnvInt("HOSTLINK_SOAK_SECONDS", 60));
        var faults = new FaultOptions
        {
            Seed = EnvInt("HOSTLINK_SOAK_SEED", 20240601),
            Drop = FaultRate,
            Corrupt = FaultRate,
            Noise = FaultRate,
            Truncate = FaultRate,
            Late = FaultRate,
            LateBy = LateBy,
        };
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = Units, Faults = faults });
        await using var host = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, 0));
        await host.StartAsync();

        var clients = new HostLinkClient[Links];
        for (int i = 0; i < Links; i++)
        {
            clients[i] = HostLinkClient.ForTcp("127.0.0.1", host.EndPoint.Port, new HostLinkClientOptions
            {
                LineTiming = Timing,
                TurnaroundAllowance = Allowance,
                ReadRetries = 2,
                WriteRetries = 0,
            });
        }

        var stats = new Stats(stalls);
        var callers = new List<Caller>();
        for (int i = 0; i < Links * CallersPerLink; i++)
        {
            callers.Add(new Caller(i, clients[i / CallersPerLink], plc, stats));
        }

        try
        {
            // Phase 1: faults.
            var clock = Stopwatch.StartNew();
            using var stop = new CancellationTokenSource(budget);
            int issued = 0;
            await Task.WhenAll(callers.Select(c => Task.Run(() => c.RunAsync(() => Interlocked.Increment(ref issued) <= target, stop.Token))));
            TimeSpan faultPhase = clock.Elapsed;

            // Phase 2: faults stop. Answers already scheduled late are still on their way: each link's session answers in
            // order, so a presence probe answered on every link (after as many tries as it takes) lands after them.
            faults.Drop = faults.Corrupt = faults.Noise = faults.Truncate = faults.Late = 0;
            foreach (HostLinkClient c in clients)
            {
                for (int tries = 0; await c.ProbeAsync(Slack) is null; tries++)
                {
                    tries.Should().BeLessThan(20, "a link answers once its late answers have landed");
                }
            }

            long faultsBefore = plc.FaultCounters.Total;
            stats.CheckBounds();
            var recovery = new Stats(stalls);
            for (int i = 0; i < 100; i++)
            {
                Caller c = callers[i % callers.Count];
                await c.OneAsync(recovery, new Random(i));
            }

            plc.FaultCounters.Total.Should().Be(faultsBefore, "no fault is injected after they are switched off");
            recovery.CheckBounds();

            // Phase 3: every write reported successful is in the simulator's memory.
            int memoryMismatches = callers.Sum(c => c.CheckMemory());

            FaultCounters f = plc.FaultCounters;
            string report = string.Join(
                Environment.NewLine,
                $"Soak: {stats.Transactions} transactions in {faultPhase.TotalSeconds:0.0} s ({stats.Transactions / faultPhase.TotalSeconds:0} /s) over {Links} links × {CallersPerLink} callers, units {string.Join(",", Units)}, fault rate {FaultRate:P0} each, seed {faults.Seed}",
                $"  reads {stats.Reads} ({stats.ReadFailures} failed), writes {stats.Writes} ({stats.WriteFailures} failed), words checked {stats.WordsChecked}",
                $"  failures by type: {Format(stats.FailuresByType)}",
                $"  faults injected: {f}",
                $"  wrong values: {stats.WrongValues}; untyped failures: {stats.Untyped}; memory mismatches after: {memoryMismatches}",
                $"  max call duration {stats.MaxDuration.TotalMilliseconds:0} ms; max ratio to its bound {stats.MaxRatio:0.00} (worst bound {stats.WorstBound.TotalMilliseconds:0} ms); over bound: {stats.OverBound}; longest runtime stall {stalls.Longest.TotalMilliseconds:0} ms, {stats.StallExtended} calls' bounds extended by stalls",
                $"  bound = callers/link {CallersPerLink} × (retries + 1) × (1 + frames) × (WireTime(262) {Timing.WireTime(262).TotalMilliseconds:0.0} ms + allowance {Allowance.TotalMilliseconds:0} ms) + slack {Slack.TotalMilliseconds:0} ms",
                $"  after faults stopped: {recovery.Transactions} calls, {recovery.Failures} failed ({Format(recovery.FailuresByType)}), wrong values {recovery.WrongValues} {recovery.FirstFailure}");
            report += string.Concat(stats.Slow.Select(x => Environment.NewLine + "  over bound: " + x));
            output.WriteLine(report);
            Console.WriteLine(report);

            stats.Transactions.Should().BeGreaterThan(Math.Min(target, 2000), "the soak must do real work in its time budget");
            stats.WrongValues.Should().Be(0, stats.FirstWrong ?? string.Empty);
            stats.Untyped.Should().Be(0, stats.FirstUntyped ?? string.Empty);
            stats.OverBound.Should().Be(0, stats.FirstOverBound ?? string.Empty);
            recovery.Failures.Should().Be(0, recovery.FirstFailure ?? string.Empty);
            recovery.WrongValues.Should().Be(0);
            memoryMismatches.Should().Be(0);
            (stats.Reads + stats.Writes).Should().Be(stats.Transactions);
            f.Dropped.Should().BeGreaterThan(0);
            f.Corrupted.Should().BeGreaterThan(0);
            f.Noise.Should().BeGreaterThan(0);
            f.Truncated.Should().BeGreaterThan(0);
            f.Late.Should().BeGreaterThan(0);
        }
        finally
        {
            foreach (HostLinkClient c in clients)
            {
                await c.DisposeAsync();
            }
        }
    }

    private static int EnvInt(string name, int fallback)
        => int.TryParse(Environment.GetEnvironmentVariable(name), NumberStyles.Integer, CultureInfo.InvariantCulture, out int v) && v > 0 ? v : fallback;

    private static string Format(ConcurrentDictionary<string, int> counts)
        => counts.IsEmpty ? "none" : string.Join(", ", counts.OrderByDescending(kv => kv.Value).Select(kv => $"{kv.Key} {kv.Value}"));

    /// <summary>The longest the link may take for one call (see the class remarks).</summary>
    private static TimeSpan Bound(int retries, int frames)
    {
        TimeSpan perFrame = Timing.WireTime(2 * FrameWriter.MaxFirstFrameLength) + Allowance;
        return (CallersPerLink * (retries + 1) * (1 + frames) * perFrame) + Slack;
    }

    /// <summary>Answer frames of a read of <paramref name="words"/> words: 30 in the first, 31 in each later one.</summary>
    private static int ReadFrames(int words) => words <= 30 ? 1 : 1 + ((words - 30 + 30) / 31);

    /// <summary>Command frames of a write of <paramref name="words"/> words (the link's own segmentation).</summary>
    private static int WriteFrames(int words) => FrameWriter.CountFrames(9 + (4 * words), 9, 4);

    private sealed class Stats(RuntimeStalls stalls)
    {
        private long _maxTicks;
        private double _maxRatio;
        private long _worstBoundTicks;
        private readonly object _gate = new();

        public int Transactions;
        public int Reads;
        public int Writes;
        public int ReadFailures;
        public int WriteFailures;
        public int Failures;
        public long WordsChecked;
        public int WrongValues;
        public int Untyped;
        public int OverBound;
        public int StallExtended;
        public string? FirstWrong;
        public string? FirstUntyped;
        public string? FirstOverBound;
        public string? FirstFailure;

        public ConcurrentDictionary<string, int> FailuresByType { get; } = new();

        public TimeSpan MaxDuration => TimeSpan.FromTicks(Interlocked.Read(ref _maxTicks));

        public double MaxRatio => _maxRatio;

        public TimeSpan WorstBound => TimeSpan.FromTicks(_worstBoundTicks);

        public List<string> Slow { get; } = new();

        private readonly ConcurrentQueue<(long End, TimeSpan Took, TimeSpan Bound, string What, Exception? Failure)> _calls = new();

        public void Duration(TimeSpan took, TimeSpan bound, string what, Exception? failure = null)
            => _calls.Enqueue((Stopwatch.GetTimestamp(), took, bound, what, failure));

        /// <summary>
        /// Checks every call against its bound, once the run is over: the bound holds for the time the process ran, so a
        /// stall of the whole runtime during the call (no timer of any link could fire) is added to it. A stall is only
        /// known once it has ended, hence afterwards.
        /// </summary>
        public void CheckBounds()
        {
            while (_calls.TryDequeue(out var call))
            {
                long start = call.End - (call.Took.Ticks * Stopwatch.Frequency / TimeSpan.TicksPerSecond);
                TimeSpan stalled = stalls.StalledWithin(start, call.End);
                Check(call.Took, stalled > TimeSpan.Zero ? call.Bound + stalled : call.Bound, stalled > TimeSpan.Zero, call.What, call.Failure);
            }
        }

        private void Check(TimeSpan took, TimeSpan bound, bool extended, string what, Exception? failure)
        {
            lock (_gate)
            {
                if (extended)
                {
                    StallExtended++;
                }

                _maxTicks = Math.Max(_maxTicks, took.Ticks);
                double ratio = took.TotalMilliseconds / bound.TotalMilliseconds;
                if (ratio > _maxRatio)
                {
                    _maxRatio = ratio;
                    _worstBoundTicks = bound.Ticks;
                }

                if (took > bound)
                {
                    OverBound++;
                    FirstOverBound ??= $"{what} took {took.TotalMilliseconds:0} ms, bound {bound.TotalMilliseconds:0} ms";
                    if (Slow.Count < 5)
                    {
                        Slow.Add($"{what} took {took.TotalMilliseconds:0} ms, bound {bound.TotalMilliseconds:0} ms: {failure?.GetType().Name} {failure?.Message}");
                    }
                }
            }
        }

        public void Failed(Exception e, string what)
        {
            Interlocked.Increment(ref Failures);
            string key = e switch
            {
                HostLinkFrameException fe => $"{nameof(HostLinkFrameException)}.{fe.Error}",
                HostLinkEndCodeException ee => $"{nameof(HostLinkEndCodeException)}.{ee.EndCode.ToCode()}",
                _ => e.GetType().Name,
            };
            FailuresByType.AddOrUpdate(key, 1, (_, n) => n + 1);
            FirstFailure ??= $"{what}: {e}";
            if (e is not HostLinkException)
            {
                Interlocked.Increment(ref Untyped);
                FirstUntyped ??= $"{what}: {e}";
            }
        }

        public void Wrong(string what)
        {
            Interlocked.Increment(ref WrongValues);
            FirstWrong ??= what;
        }
    }

    /// <summary>One concurrent caller: its own DM and HR words, its own model of them, several units on its link.</summary>
    private sealed class Caller
    {
        private readonly int _index;
        private readonly HostLinkUnit[] _units;
        private readonly VirtualPlc _plc;
        private readonly Stats _stats;
        private readonly int _dmBase;
        private readonly int _hrBase;
        private readonly HashSet<ushort>[] _dm = Enumerable.Range(0, DmWords).Select(_ => new HashSet<ushort> { 0 }).ToArray();
        private readonly HashSet<ushort>[] _hr = Enumerable.Range(0, HrWords).Select(_ => new HashSet<ushort> { 0 }).ToArray();

        public Caller(int index, HostLinkClient client, VirtualPlc plc, Stats stats)
        {
            _index = index;
            _units = Units.Select(u => client.Unit(u)).ToArray();
            _plc = plc;
            _stats = stats;
            _dmBase = 1000 + (index * 100);
            _hrBase = index * 20;
        }

        public async Task RunAsync(Func<bool> more, CancellationToken stop)
        {
            var random = new Random(7919 * (_index + 1));
            while (!stop.IsCancellationRequested && more())
            {
                await OneAsync(_stats, random);
            }
        }

        public async Task OneAsync(Stats stats, Random random)
        {
            HostLinkUnit unit = _units[random.Next(_units.Length)];
            bool hr = random.Next(5) == 0;
            HashSet<ushort>[] model = hr ? _hr : _dm;
            int size = model.Length;
            int count = 1 + random.Next(hr ? HrWords : DmWords);
            int offset = random.Next(size - count + 1);
            string address = hr ? $"H{_hrBase + offset}" : $"D{_dmBase + offset}";
            bool write = random.Next(100) < 40;
            Interlocked.Increment(ref stats.Transactions);
            if (write)
            {
                Interlocked.Increment(ref stats.Writes);
                ushort[] values = Enumerable.Range(0, count).Select(_ => (ushort)random.Next(0x10000)).ToArray();
                string what = $"caller {_index} unit {unit.UnitNumber} write {address} × {count}";
                var clock = Stopwatch.StartNew();
                try
                {
                    await unit.WriteWordsAsync(address, values);
                    stats.Duration(clock.Elapsed, Bound(0, WriteFrames(count)), what);
                    for (int i = 0; i < count; i++)
                    {
                        model[offset + i].Clear();
                        model[offset + i].Add(values[i]);
                    }
                }
                catch (Exception e)
                {
                    stats.Duration(clock.Elapsed, Bound(0, WriteFrames(count)), what, e);
                    Interlocked.Increment(ref stats.WriteFailures);
                    stats.Failed(e, what);

                    // Not known whether the PLC executed it: either value may be there now.
                    for (int i = 0; i < count; i++)
                    {
                        model[offset + i].Add(values[i]);
                    }
                }
            }
            else
            {
                Interlocked.Increment(ref stats.Reads);
                string what = $"caller {_index} unit {unit.UnitNumber} read {address} × {count}";
                var clock = Stopwatch.StartNew();
                try
                {
                    ushort[] words = await unit.ReadWordsAsync(address, count);
                    stats.Duration(clock.Elapsed, Bound(2, ReadFrames(count)), what);
                    if (words.Length != count)
                    {
                        stats.Wrong($"{what}: {words.Length} words returned");
                        return;
                    }

                    Interlocked.Add(ref stats.WordsChecked, count);
                    for (int i = 0; i < count; i++)
                    {
                        HashSet<ushort> possible = model[offset + i];
                        if (!possible.Contains(words[i]))
                        {
                            stats.Wrong($"{what}: word {i} is {words[i]:X4}, expected one of {string.Join(",", possible.Select(p => p.ToString("X4", CultureInfo.InvariantCulture)))}");
                        }

                        possible.Clear();
                        possible.Add(words[i]);
                    }
                }
                catch (Exception e)
                {
                    stats.Duration(clock.Elapsed, Bound(2, ReadFrames(count)), what, e);
                    Interlocked.Increment(ref stats.ReadFailures);
                    stats.Failed(e, what);
                }
            }
        }

        /// <summary>Compares the model with the simulator's memory; returns the number of words that differ.</summary>
        public int CheckMemory()
        {
            int bad = 0;
            ushort[] dm = _plc.ReadWords(PlcArea.Dm, _dmBase, DmWords);
            ushort[] hr = _plc.ReadWords(PlcArea.Holding, _hrBase, HrWords);
            for (int i = 0; i < DmWords; i++)
            {
                bad += _dm[i].Contains(dm[i]) ? 0 : 1;
            }

            for (int i = 0; i < HrWords; i++)
            {
                bad += _hr[i].Contains(hr[i]) ? 0 : 1;
            }

            return bad;
        }
    }
}

/// <summary>Timing-sensitive tests run alone, after the parallel ones, so that other tests do not eat their deadlines.</summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class SoakCollection
{
    public const string Name = "Reliability (not parallel)";
}
