using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>Change subscriptions: the tags polled with one planned read a cycle, changes and outages as events.</summary>
public partial class HostLinkUnit
{
    /// <inheritdoc cref="WatchAsync(IReadOnlyList{PlcTag}, WatchOptions, CancellationToken)"/>
    /// <param name="tags">The tags; tags without a unit are read from this unit.</param>
    /// <param name="interval">The time from the start of one cycle to the start of the next; zero polls back to back.</param>
    /// <param name="cancellationToken">Ends the watch.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="interval"/> is negative or over 1 day.</exception>
    public IAsyncEnumerable<WatchEvent> WatchAsync(IReadOnlyList<PlcTag> tags, TimeSpan interval, CancellationToken cancellationToken = default)
    {
        WatchOptions.CheckInterval(interval, nameof(interval));
        return WatchAsync(tags, new WatchOptions { Interval = interval }, cancellationToken);
    }

    /// <summary>
    /// Watches <paramref name="tags"/> for changes: each cycle reads them all with one execution of a plan made by
    /// <see cref="ReadPlanner"/> (the fewest transactions, as <see cref="ReadTagsAsync(IReadOnlyList{PlcTag}, CancellationToken)"/>:
    /// QQ where <see cref="HostLinkClientOptions.UseCompoundRead"/> gives a unit one), and reports each tag whose value
    /// differs from the one reported before. The plan is made at once with what is known without asking the PLC, and
    /// again after the first successful cycle when the PLC's answers change it: with
    /// <see cref="CompoundReadMode.Auto"/> and no configured model the unit is asked MM once, then; a unit that refuses
    /// QQ is read by area from then on. A PLC holds one QQ registration a unit: of several watches on one unit, the one
    /// QQ saves the most characters a second for uses it, the others read that unit by area. With
    /// <see cref="WatchOptions.ReportPlans"/> each plan is reported as <see cref="WatchEventKind.Planned"/>. The first successful cycle reports every tag
    /// (with no old value). A failed cycle is reported once as <see cref="WatchEventKind.Outage"/> and the watch keeps
    /// trying every <see cref="WatchOptions.RetryInterval"/> (doubling up to <see cref="WatchOptions.MaxRetryInterval"/>
    /// when that is set); the first cycle that succeeds again is reported as
    /// <see cref="WatchEventKind.Resumed"/>, followed by the changes since. A cycle longer than the interval is reported
    /// as <see cref="WatchEventKind.Overrun"/>, and the next starts at once. With <see cref="WatchOptions.ReportEveryCycle"/>
    /// every successful cycle also ends with <see cref="WatchEventKind.Polled"/>, and every further failed try of an
    /// outage is <see cref="WatchEventKind.RetryFailed"/>. With <see cref="WatchOptions.DemoteAfter"/> set, a unit that
    /// stays silent that many cycles in a row is <see cref="WatchEventKind.Demoted"/>: no read for the demotion period,
    /// then one presence probe of each unit the plan reads decides whether the watch reads again.
    /// </summary>
    /// <remarks>
    /// The watch runs while it is enumerated (<c>await foreach</c>): cycles are not read ahead, so a slow subscriber
    /// slows the polling (and sees overruns) rather than a queue growing. Each enumeration is its own watch. Only the
    /// subscriber ends it: by leaving the loop, or by cancelling <paramref name="cancellationToken"/> (or the token given
    /// to <c>WithCancellation</c>), which ends the loop with <see cref="OperationCanceledException"/> as every cancelled
    /// operation of the library does; link failures never end it. A client disposed under a running watch ends it with
    /// <see cref="ObjectDisposedException"/>.
    /// </remarks>
    /// <param name="tags">The tags, at least one; tags without a unit are read from this unit.</param>
    /// <param name="options">The interval, the retry interval and the clock.</param>
    /// <param name="cancellationToken">Ends the watch.</param>
    /// <returns>The events, as they happen.</returns>
    /// <exception cref="ArgumentException">No tags, or a tag cannot be read with this view's command set (thrown by this call, before any read).</exception>
    /// <exception cref="ArgumentOutOfRangeException">An option is out of range.</exception>
    public IAsyncEnumerable<WatchEvent> WatchAsync(IReadOnlyList<PlcTag> tags, WatchOptions options, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(tags);
        Guard.NotNull(options);
        options.Validate();
        if (tags.Count == 0)
        {
            throw new ArgumentException("Give at least one tag to watch.", nameof(tags));
        }

        var planned = new PlannedTags(this, tags.ToArray(), options.Interval);

        // A copy: the caller may change or reuse its options while the watch runs.
        var settings = new WatchOptions
        {
            Interval = options.Interval,
            RetryInterval = options.RetryInterval,
            MaxRetryInterval = options.MaxRetryInterval,
            ReportEveryCycle = options.ReportEveryCycle,
            ReportPlans = options.ReportPlans,
            DemoteAfter = options.DemoteAfter,
            DemotionPeriod = options.DemotionPeriod,
            TimeProvider = options.TimeProvider,
            ScheduleStart = options.ScheduleStart,
        };
        return TagWatch.RunAsync(this, planned, settings, cancellationToken);
    }
}
