using System.Runtime.CompilerServices;
using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// The polling engine behind <c>WatchAsync</c>: one execution of a read plan per cycle, changes against the values
/// reported before, outages and overruns as events, retries after a fixed or a capped doubling delay.
/// </summary>
/// <remarks>
/// Cycles keep a fixed schedule: each is due one interval after the one before was due, not after it began, so a
/// timer that wakes late does not push the cycles after it later (the phase does not drift), and one that wakes a
/// little early (the system timer can, by the stopwatch's clock) does not make the next cycle due sooner. When the
/// subscriber asks for more events after the next cycle was due (the read was slow, or handling the events was), an
/// overrun is reported and that cycle starts at once, in the place of the scheduled time nearest to it (the latest
/// already past, or the next); the one after it is due at the scheduled time after that, so no backlog of cycles piles
/// up and a long cycle is not followed by cycles back to back. A failed read's retries and a
/// demoted unit's probes wait their own delays from the failure, and the schedule starts again from the cycle that
/// reads.
/// </remarks>
internal static class TagWatch
{
    public static async IAsyncEnumerable<WatchEvent> RunAsync(
        HostLinkUnit unit,
        PlannedTags planned,
        WatchOptions options,
        [EnumeratorCancellation] CancellationToken cancellationToken)
    {
        TimeSpan interval = options.Interval;
        TimeProvider time = options.TimeProvider;
        bool everyCycle = options.ReportEveryCycle;
        TimeSpan retryDelay = options.EffectiveRetryInterval;
        IReadOnlyList<PlcTag> tags = planned.Current.Tags;
        var reported = new PlcValue?[tags.Count];
        long origin = time.GetTimestamp();
        TimeSpan cycleStart = TimeSpan.Zero;
        TimeSpan due = options.ScheduleStart is { } start ? time.GetElapsedTime(origin, start) : TimeSpan.Zero;
        bool succeeded = false;
        bool answered = false;
        TimeSpan? outageStart = null;
        int silentCycles = 0;
        bool demoted = false;

        try
        {
            while (true)
            {
                cancellationToken.ThrowIfCancellationRequested();
                TimeSpan now = time.GetElapsedTime(origin);
                if (now < due)
                {
                    await Delay(due - now, time, cancellationToken).ConfigureAwait(false);
                }
                else if (interval > TimeSpan.Zero && now > due)
                {
                    due = LatePlace(due, now, interval);
                    if (succeeded)
                    {
                        yield return WatchEvent.Overrun(now - cycleStart, time.GetUtcNow());
                    }
                }

                if (demoted && await ProbeAsync(unit, planned.Current, cancellationToken).ConfigureAwait(false) is { } silent)
                {
                    // Still silent: one more period without a read.
                    due = time.GetElapsedTime(origin) + options.DemotionPeriod;
                    if (everyCycle)
                    {
                        yield return WatchEvent.RetryFailed(silent, time.GetUtcNow(), options.DemotionPeriod);
                    }

                    continue;
                }

                cycleStart = time.GetElapsedTime(origin);
                PlcTagValue[]? values = null;
                Exception? failure = null;
                ReadPlan? plan = null;
                bool replanned = false;
                try
                {
                    // What decides the plan may need the PLC (a model asked with MM once): part of the cycle, and of its failure.
                    (plan, replanned) = await planned.PlanAsync(askPlc: answered, cancellationToken).ConfigureAwait(false);
                }
                catch (Exception e) when (IsCycleFailure(e, cancellationToken))
                {
                    failure = e;
                }

                if (replanned && options.ReportPlans)
                {
                    yield return WatchEvent.Planned(plan!, time.GetUtcNow());
                }

                if (failure is null)
                {
                    try
                    {
                        values = await unit.ReadTagsAsync(plan!, cancellationToken).ConfigureAwait(false);
                    }
                    catch (Exception e) when (IsCycleFailure(e, cancellationToken))
                    {
                        failure = e;
                    }
                }

                DateTimeOffset readTime = time.GetUtcNow();
                TimeSpan end = time.GetElapsedTime(origin);
                if (failure is not null)
                {
                    succeeded = false;
                    silentCycles = IsSilence(failure) ? silentCycles + 1 : failure is HostLinkConnectionException ? silentCycles : 0;
                    bool demote = options.DemoteAfter > 0 && silentCycles >= options.DemoteAfter;
                    bool first = outageStart is null;
                    if (first)
                    {
                        outageStart = end;
                        retryDelay = options.EffectiveRetryInterval;
                    }
                    else if (!demote)
                    {
                        retryDelay = options.NextRetryDelay(retryDelay);
                    }

                    TimeSpan wait = demote ? options.DemotionPeriod : retryDelay;
                    due = end + wait;
                    if (first)
                    {
                        yield return WatchEvent.Outage(failure, readTime, wait);
                    }

                    if (demote && !demoted)
                    {
                        demoted = true;
                        yield return WatchEvent.Demoted(failure, readTime, wait);
                    }
                    else if (!first && everyCycle)
                    {
                        yield return WatchEvent.RetryFailed(failure, readTime, wait);
                    }

                    demoted = demote;
                    continue;
                }

                succeeded = true;
                answered = true;
                silentCycles = 0;
                demoted = false;
                due += interval;
                if (outageStart is { } since)
                {
                    outageStart = null;
                    yield return WatchEvent.Resumed(end - since, readTime);
                }

                for (int i = 0; i < values!.Length; i++)
                {
                    PlcValue value = Decode(values[i], unit.WordOrder);
                    if (reported[i] is { } old && old == value)
                    {
                        continue;
                    }

                    PlcValue? previous = reported[i];
                    reported[i] = value;
                    yield return WatchEvent.Changed(i, tags[i], previous, value, readTime, values[i].Words);
                }

                if (everyCycle)
                {
                    yield return WatchEvent.Polled(end - cycleStart, readTime);
                }
            }
        }
        finally
        {
            // The unit's QQ registration is left to the other watches.
            planned.Release();
        }
    }

    /// <summary>
    /// The place in the schedule of a cycle found late (due at <paramref name="due"/>, started at <paramref name="now"/>):
    /// the scheduled time nearest to its start, the latest already past or the next. The cycles skipped are not made
    /// up, and after a long cycle the next is due about an interval on, not at once again and again while the late
    /// start is caught up a little each cycle.
    /// </summary>
    internal static TimeSpan LatePlace(TimeSpan due, TimeSpan now, TimeSpan interval)
        => due + TimeSpan.FromTicks(((now - due).Ticks + (interval.Ticks / 2)) / interval.Ticks * interval.Ticks);

    /// <summary>
    /// Whether a failed read is an outage to report and outlive: the library's own failures, the stream's, a value that
    /// does not decode, and a cancellation that is not the subscriber's (a connect timeout). The subscriber's
    /// cancellation and programming errors (a disposed client) end the watch instead.
    /// </summary>
    private static bool IsCycleFailure(Exception e, CancellationToken cancellationToken) => e switch
    {
        OperationCanceledException => !cancellationToken.IsCancellationRequested,
        ObjectDisposedException => false,
        HostLinkException or IOException or FormatException or TimeoutException => true,
        _ => false,
    };

    /// <summary>A failure that says the unit did not answer at all (not a damaged answer, an end code or a lost port).</summary>
    private static bool IsSilence(Exception e) => e is HostLinkTimeoutException or TimeoutException;

    /// <summary>
    /// Asks each unit the plan reads, with one presence probe, whether it answers; the first unit's silence as an
    /// exception, or null when every unit answered. A port that cannot be opened counts as silence.
    /// </summary>
    private static async Task<Exception?> ProbeAsync(HostLinkUnit unit, ReadPlan plan, CancellationToken cancellationToken)
    {
        foreach (int number in plan.TagUnits.Distinct())
        {
            HostLinkUnit view = number == unit.UnitNumber ? unit : unit.Unit(number);
            try
            {
                if (await view.ProbeAsync(null, cancellationToken).ConfigureAwait(false) is null)
                {
                    TimeSpan turnaround = view.TurnaroundAllowance;
                    return new HostLinkTimeoutException(
                        $"Unit {number:D2} did not answer a presence probe (TS) within its turnaround allowance ({turnaround.TotalMilliseconds:0} ms) after the frame's time on the wire; it stays demoted.",
                        turnaround);
                }
            }
            catch (HostLinkConnectionException e)
            {
                return e;
            }
        }

        return null;
    }

    // The value in the tag's type, decoded from the words read, compared bit for bit (a REAL NaN equals itself).
    private static PlcValue Decode(PlcTagValue value, WordOrder order)
    {
        IReadOnlyList<ushort> words = value.Words;
        Span<ushort> raw = stackalloc ushort[words.Count];
        for (int i = 0; i < raw.Length; i++)
        {
            raw[i] = words[i];
        }

        PlcTag tag = value.Tag;
        return PlcValueCodec.Decode(tag.Type, raw, order, tag.Address.IsBit ? tag.Address.Bit : 0);
    }

    private static Task Delay(TimeSpan delay, TimeProvider time, CancellationToken cancellationToken)
#if NET
        => Task.Delay(delay, time, cancellationToken);
#else
        => time.Delay(delay, cancellationToken);
#endif
}
