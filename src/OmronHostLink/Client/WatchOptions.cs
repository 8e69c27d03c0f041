namespace OmronHostLink;

/// <summary>How <see cref="HostLinkUnit.WatchAsync(IReadOnlyList{Planning.PlcTag}, WatchOptions, CancellationToken)"/> polls.</summary>
public sealed class WatchOptions
{
    private static readonly TimeSpan MaxInterval = TimeSpan.FromDays(1);

    /// <summary>The most failed cycles <see cref="DemoteAfter"/> may wait for.</summary>
    public const int MaxDemoteAfter = 1000;

    /// <summary>
    /// The time from the start of one cycle to the start of the next. <see cref="TimeSpan.Zero"/> polls back to back
    /// (and never reports an overrun). Default 1 s; at most 1 day.
    /// </summary>
    public TimeSpan Interval { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>
    /// How long after a failed cycle the next try starts. Null (the default) for <see cref="Interval"/>, but at least
    /// 1 s, so an outage does not become a tight loop of failing exchanges.
    /// </summary>
    public TimeSpan? RetryInterval { get; set; }

    /// <summary>
    /// The longest wait between tries during an outage. Null (the default): every try waits the retry interval in force.
    /// Set: the wait starts at the retry interval in force and doubles after each failed try, up to this (capped
    /// exponential backoff), so a PLC that stays away costs the line less and less. At least the retry interval in
    /// force; at most 1 day.
    /// </summary>
    public TimeSpan? MaxRetryInterval { get; set; }

    /// <summary>
    /// Also report what changes nothing: <see cref="WatchEventKind.Polled"/> after every successful cycle (after the
    /// cycle's changes) and <see cref="WatchEventKind.RetryFailed"/> for every failed try of an outage after the first.
    /// Default false. For subscribers that log, count or time every poll.
    /// </summary>
    public bool ReportEveryCycle { get; set; }

    /// <summary>
    /// Also report the reads the watch makes: <see cref="WatchEventKind.Planned"/> before the first cycle and whenever
    /// the plan changes (a unit's model learnt with MM, a unit that refused QQ). Default false. For subscribers that
    /// show or budget the line's load.
    /// </summary>
    public bool ReportPlans { get; set; }

    /// <summary>
    /// Demote the watched unit after this many cycles in a row found it silent (a timeout): the watch reports
    /// <see cref="WatchEventKind.Demoted"/> and stops reading for <see cref="DemotionPeriod"/>, then asks the unit with
    /// one presence probe (<see cref="HostLinkUnit.ProbeAsync"/>: one TS, never retried, one short deadline) whether it
    /// is back before it reads again, so a dead unit on a multidrop line costs one probe a period instead of a read with
    /// every retry. A cycle the unit answers, even with an error, starts the count again. 0 (the default) never demotes;
    /// at most 1000.
    /// </summary>
    public int DemoteAfter { get; set; }

    /// <summary>How long a demoted unit is not read before the next probe. Default 10 s; more than 0 and at most 1 day.</summary>
    public TimeSpan DemotionPeriod { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>The clock for intervals and event timestamps. Default <see cref="TimeProvider.System"/>; tests pass a fake one.</summary>
    public TimeProvider TimeProvider { get; set; } = TimeProvider.System;

    /// <summary>
    /// Where the schedule is anchored, as a timestamp of <see cref="TimeProvider"/>: cycles are due at it plus whole
    /// intervals (the first cycle at the first of those times not yet past, or at once in the place of the one nearest
    /// to its start), so watches started together keep the phases they were given however late each one starts. Null (the
    /// default): the schedule starts with the watch's first cycle.
    /// </summary>
    internal long? ScheduleStart { get; set; }

    /// <summary>The retry interval in force: <see cref="RetryInterval"/>, or <see cref="Interval"/> but at least 1 s.</summary>
    internal TimeSpan EffectiveRetryInterval
        => RetryInterval ?? (Interval > TimeSpan.FromSeconds(1) ? Interval : TimeSpan.FromSeconds(1));

    /// <summary>The wait after a failed try that followed a wait of <paramref name="previous"/>: doubled up to <see cref="MaxRetryInterval"/>, or the same.</summary>
    internal TimeSpan NextRetryDelay(TimeSpan previous)
        => MaxRetryInterval is { } max ? TimeSpan.FromTicks(Math.Min(previous.Ticks * 2, max.Ticks)) : previous;

    /// <summary>Checks the options and says which is wrong.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><see cref="Interval"/>, <see cref="RetryInterval"/> or <see cref="MaxRetryInterval"/> is out of range.</exception>
    /// <exception cref="ArgumentNullException"><see cref="TimeProvider"/> is null.</exception>
    public void Validate()
    {
        CheckInterval(Interval, nameof(Interval));
        if (RetryInterval is { } retry && (retry <= TimeSpan.Zero || retry > MaxInterval))
        {
            throw new ArgumentOutOfRangeException(nameof(RetryInterval), retry, $"RetryInterval must be more than 0 and at most 1 day; it was {retry}.");
        }

        if (MaxRetryInterval is { } max && (max > MaxInterval || max < EffectiveRetryInterval))
        {
            throw new ArgumentOutOfRangeException(nameof(MaxRetryInterval), max, $"MaxRetryInterval must be at least the retry interval ({EffectiveRetryInterval}) and at most 1 day; it was {max}.");
        }

        if (DemoteAfter is < 0 or > MaxDemoteAfter)
        {
            throw new ArgumentOutOfRangeException(nameof(DemoteAfter), DemoteAfter, $"DemoteAfter must be 0 (never) up to {MaxDemoteAfter}; it was {DemoteAfter}.");
        }

        if (DemotionPeriod <= TimeSpan.Zero || DemotionPeriod > MaxInterval)
        {
            throw new ArgumentOutOfRangeException(nameof(DemotionPeriod), DemotionPeriod, $"DemotionPeriod must be more than 0 and at most 1 day; it was {DemotionPeriod}.");
        }

        if (TimeProvider is null)
        {
            throw new ArgumentNullException(nameof(TimeProvider), "TimeProvider is required; use TimeProvider.System for the real clock.");
        }
    }

    internal static void CheckInterval(TimeSpan interval, string name)
    {
        if (interval < TimeSpan.Zero || interval > MaxInterval)
        {
            throw new ArgumentOutOfRangeException(name, interval, $"{name} must be 0 (back to back) up to 1 day; it was {interval}.");
        }
    }
}
