using OmronHostLink.Planning;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// The cycle each scan class of one line can expect when the classes share it: a deterministic run of the line's
/// schedule as the gateway polls it. Every class is one watch that starts at its phase (<see cref="Phases"/>) and keeps
/// a fixed schedule from there: each cycle due one interval after the one before was due, a cycle found late started
/// at once in the place of the scheduled time nearest to it. A cycle makes its reads one after another, each an
/// exchange the line's gate runs whole and the host's hand-over to the next (<see cref="HandOver"/>); readers that wait
/// for the gate take it in the order they asked (SemaphoreSlim's queue; a QQ read too, whose registration gate is its
/// unit's alone), so a read waits for at most one read of each other class, and a class's cycle stretches by the reads
/// of the others that come between its own. A cycle is measured as the watch does: from its start to its last answer.
/// </summary>
/// <remarks>
/// A queueing formula with random phases misses what rules such a line: classes of one interval keep their phases, so
/// they wait for each other the same way cycle after cycle, and a class's read waits behind the reads other classes
/// queued first. The classes' phases (<see cref="Phases"/>) fix the order in which they come due rather than leave it
/// to which of the host's timers wakes first; the run follows those phases. Run for
/// twenty of the longest intervals after the first, each class at least one cycle after it (every class reads at once
/// at the start, and cycles begun within the first longest interval are left out), or until 200,000 reads, each class
/// at least one cycle (its cycles at the start counted when it has no other).
/// </remarks>
internal static class LineSchedule
{
    private const int Horizon = 20;
    private const long MaxReads = 200_000;

    /// <summary>
    /// How far apart any two of a link's scan classes come due at the least (where their phases allow): more than a
    /// timer's lateness on a busy host, so that the classes come due in a fixed order every cycle, and little against
    /// the shortest intervals.
    /// </summary>
    public static readonly TimeSpan Stagger = TimeSpan.FromMilliseconds(10);

    private static readonly TimeSpan Step = TimeSpan.FromMilliseconds(1);
    private const int MaxSteps = 1000;

    /// <summary>
    /// When each of a link's scan classes (their intervals in configuration order) comes due, after the link's start:
    /// the classes of one interval spread evenly across it (the second of two every-second classes half a second after
    /// the first), so that they do not queue for the line together every cycle and hold a faster class up behind all
    /// of their reads; and each moved on from there, a millisecond at a time, until it comes due at least
    /// <see cref="Stagger"/> from every class placed before it — on its own cycle and theirs, which meet every
    /// greatest common divisor of the two intervals — so that no two come due at one instant, which the host's timers
    /// would order as they happen to wake. Where no place is that far from all (many classes on short intervals), the
    /// farthest found is taken.
    /// </summary>
    public static TimeSpan[] Phases(IReadOnlyList<TimeSpan> intervals)
    {
        var phases = new TimeSpan[intervals.Count];
        for (int i = 0; i < phases.Length; i++)
        {
            TimeSpan interval = intervals[i];
            int alike = intervals.Count(x => x == interval);
            int before = intervals.Take(i).Count(x => x == interval);
            TimeSpan spread = alike > 1 ? TimeSpan.FromTicks(interval.Ticks / alike * before) : TimeSpan.Zero;
            TimeSpan best = spread;
            long bestDistance = -1;
            for (int step = 0; step < MaxSteps && interval > TimeSpan.Zero; step++)
            {
                TimeSpan candidate = spread + (Step * step);
                long distance = long.MaxValue;
                for (int j = 0; j < i; j++)
                {
                    if (intervals[j] > TimeSpan.Zero)
                    {
                        long meet = Gcd(interval.Ticks, intervals[j].Ticks);
                        long apart = (((candidate - phases[j]).Ticks % meet) + meet) % meet;
                        distance = Math.Min(distance, Math.Min(apart, meet - apart));
                    }
                }

                if (distance > bestDistance)
                {
                    best = candidate;
                    bestDistance = distance;
                }

                if (distance >= Stagger.Ticks)
                {
                    break;
                }
            }

            phases[i] = best;
        }

        return phases;
    }

    private static long Gcd(long a, long b)
    {
        while (b != 0)
        {
            (a, b) = (b, a % b);
        }

        return a;
    }

    /// <summary>
    /// The latest of a class's scheduled times at or before the link's start (its phase less whole intervals): the
    /// anchor its watch is given, so that its first cycle runs at once, as every class's does, and the next on its phase.
    /// </summary>
    public static TimeSpan Anchor(TimeSpan phase, TimeSpan interval)
        => interval <= TimeSpan.Zero || phase <= TimeSpan.Zero ? TimeSpan.Zero : phase - TimeSpan.FromTicks((phase.Ticks + interval.Ticks - 1) / interval.Ticks * interval.Ticks);

    /// <summary>
    /// One scan class on the line: its interval, the time of each of its reads (the send gap included), and its phase
    /// after the link's start (<see cref="Phases"/>), where its schedule lies; its first cycle runs at once.
    /// </summary>
    public readonly record struct Watch(TimeSpan Interval, IReadOnlyList<TimeSpan> Reads, TimeSpan Start)
    {
        /// <summary>The class's own time on the line a cycle.</summary>
        public TimeSpan LineTime => TimeSpan.FromTicks(Reads.Sum(r => r.Ticks));
    }

    /// <summary>
    /// The host's time a read takes beyond its characters: from a watch's wake (or the answer before, for the next read
    /// of a cycle) to its command on the line, and from its last answer to the cycle's end — the gate handed over, the
    /// waiting reader run, its command built and written. Measured with the mixed-scan benchmark (a gateway polling 8
    /// units on 4 links of 38400 bps, loopback to the emulated serial-device servers): 0.86 ms median for a cycle's
    /// first read (0.67 ms to the command, 0.19 ms after the answer), 0.44 ms between two reads.
    /// </summary>
    public static readonly TimeSpan HandOver = TimeSpan.FromMilliseconds(0.75);

    /// <summary>The reads of <paramref name="plan"/> as times on the line: each one's characters and turnarounds, and the send gap before it.</summary>
    public static TimeSpan[] Reads(ReadPlan plan, TimeSpan gap)
        => plan.Reads.Select(r => plan.Cost.Time(r.Characters, r.Exchanges) + gap).ToArray();

    /// <summary>Each watch's expected cycle on the shared line: each read its time on the line and the host's <see cref="HandOver"/>.</summary>
    public static TimeSpan[] ExpectedCycles(IReadOnlyList<Watch> watches)
    {
        int n = watches.Count;
        var cycles = new TimeSpan[n];
        if (n == 0)
        {
            return cycles;
        }

        if (n == 1 || watches.All(w => w.Reads.Count == 0))
        {
            for (int i = 0; i < n; i++)
            {
                cycles[i] = Alone(watches[i]);
            }

            return cycles;
        }

        long warmUp = watches.Max(w => w.Interval.Ticks);
        long horizon = warmUp * (Horizon + 1);
        var next = new int[n];
        var start = new long[n];
        var slot = new long[n];
        var count = new long[n];
        var total = new long[n];
        var cycled = new long[n];
        var totalCycled = new long[n];

        // Watches by the time they come due; at one instant, in their order.
        var due = new PriorityQueue<int, (long At, int Rank)>();
        var gate = new Queue<int>();
        for (int i = 0; i < n; i++)
        {
            if (watches[i].Reads.Count > 0)
            {
                // Every class reads at once at the start, then on its phase's schedule.
                TimeSpan anchor = Anchor(watches[i].Start, watches[i].Interval);
                slot[i] = (anchor < TimeSpan.Zero ? TagWatch.LatePlace(anchor, TimeSpan.Zero, watches[i].Interval) : anchor).Ticks;
                due.Enqueue(i, (0, i));
            }
        }

        long now = 0;
        long reads = 0;
        while (true)
        {
            Arrive(due, gate, next, start, now, inclusive: true);
            if (!gate.TryDequeue(out int reader))
            {
                // The line is idle until the next watch comes due.
                if (!due.TryPeek(out _, out (long At, int Rank) first))
                {
                    break;
                }

                now = first.At;
                continue;
            }

            now += watches[reader].Reads[next[reader]].Ticks + HandOver.Ticks;
            reads++;

            // Watches that came due during the read asked for the gate before this reader asks again.
            Arrive(due, gate, next, start, now, inclusive: false);
            if (++next[reader] < watches[reader].Reads.Count)
            {
                gate.Enqueue(reader);
            }
            else
            {
                // The start, where every class reads at once and the late find their places, is not the schedule's:
                // cycles begun within the longest interval are left out of the expectation.
                if (start[reader] >= warmUp)
                {
                    count[reader]++;
                    total[reader] += now - start[reader];
                }

                cycled[reader]++;
                totalCycled[reader] += now - start[reader];

                long interval = watches[reader].Interval.Ticks;
                long at = slot[reader] + interval;
                if (at < now)
                {
                    // Late: the next cycle starts at once, in its place as the watch gives it (TagWatch.LatePlace).
                    slot[reader] = interval == 0 ? now : TagWatch.LatePlace(TimeSpan.FromTicks(at), TimeSpan.FromTicks(now), TimeSpan.FromTicks(interval)).Ticks;
                    at = now;
                }
                else
                {
                    slot[reader] = at;
                }

                due.Enqueue(reader, (at, reader));
            }

            // Past the horizon once every class has a cycle after the start; at the read limit, once every class has one
            // at all (a class of a day beside one of milliseconds is not run for a day of reads).
            if ((now >= horizon && AllCycled(count, watches)) || (reads >= MaxReads && AllCycled(cycled, watches)))
            {
                break;
            }
        }

        for (int i = 0; i < n; i++)
        {
            cycles[i] = count[i] > 0 ? TimeSpan.FromTicks(total[i] / count[i])
                : cycled[i] > 0 ? TimeSpan.FromTicks(totalCycled[i] / cycled[i])
                : Alone(watches[i]);
        }

        return cycles;
    }

    /// <summary>A watch's cycle with the line to itself: its time on the line and the host's hand-over of each read.</summary>
    private static TimeSpan Alone(Watch watch) => watch.LineTime + (HandOver * watch.Reads.Count);

    /// <summary>Watches due by <paramref name="now"/> begin a cycle and queue for the gate.</summary>
    private static void Arrive(PriorityQueue<int, (long At, int Rank)> due, Queue<int> gate, int[] next, long[] start, long now, bool inclusive)
    {
        while (due.TryPeek(out int watch, out (long At, int Rank) when) && (when.At < now || (inclusive && when.At == now)))
        {
            due.Dequeue();
            next[watch] = 0;
            start[watch] = when.At;
            gate.Enqueue(watch);
        }
    }

    /// <summary>Whether every watch with reads has a cycle counted.</summary>
    private static bool AllCycled(long[] count, IReadOnlyList<Watch> watches)
    {
        for (int i = 0; i < count.Length; i++)
        {
            if (count[i] == 0 && watches[i].Reads.Count > 0)
            {
                return false;
            }
        }

        return true;
    }
}
