using System.Diagnostics;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// Changes the simulators' memory on a fixed schedule: every tag once per <c>period</c>, the tags' phases spread
/// evenly over the period (tag s of M at s × period / M), so changes come at a steady rate of M / period a second. A
/// period longer than the poll interval means no change can be legitimately coalesced with the next: each must
/// reach the subscriber.
/// </summary>
internal static class ChangeWriter
{
    /// <summary>
    /// Writes for <paramref name="duration"/> (bounded by it and by the ledger's capacity), recording each change's
    /// time in <paramref name="ledger"/> just before the write.
    /// </summary>
    /// <param name="plcs">The PLC of each link.</param>
    /// <param name="words">The D word of each tag of a link.</param>
    /// <param name="ledger">Tag t of link l is <c>l × words.Length + t</c>.</param>
    /// <param name="period">Time between two changes of one tag.</param>
    /// <param name="duration">How long to write.</param>
    /// <param name="cancellationToken">Stops early.</param>
    /// <returns>The changes written.</returns>
    public static async Task<long> RunAsync(IReadOnlyList<VirtualPlc> plcs, IReadOnlyList<int> words, ChangeLedger ledger, TimeSpan period, TimeSpan duration, CancellationToken cancellationToken)
    {
        int slots = plcs.Count * words.Count;
        long rounds = (long)Math.Ceiling(duration / period);
        long total = rounds * slots;
        long periodTicks = (long)(period.TotalSeconds * Stopwatch.Frequency);
        long durationTicks = (long)(duration.TotalSeconds * Stopwatch.Frequency);
        long start = Stopwatch.GetTimestamp();
        long written = 0;
        for (long e = 0; e < total; e++)
        {
            long round = e / slots;
            int slot = (int)(e % slots);
            long due = start + (round * periodTicks) + (slot * periodTicks / slots);
            if (due - start >= durationTicks)
            {
                break;
            }

            long wait = due - Stopwatch.GetTimestamp();
            if (wait > Stopwatch.Frequency / 1000)
            {
                await Task.Delay(TimeSpan.FromSeconds((double)wait / Stopwatch.Frequency), cancellationToken).ConfigureAwait(false);
            }

            cancellationToken.ThrowIfCancellationRequested();
            int link = slot / words.Count;
            int tag = slot % words.Count;
            ushort value = ledger.NextValue(slot);
            long now = Stopwatch.GetTimestamp();
            plcs[link].WriteWord(PlcArea.Dm, words[tag], value);
            ledger.Written(slot, now);
            written++;
        }

        return written;
    }
}
