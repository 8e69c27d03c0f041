namespace OmronHostLink;

/// <summary>What a <see cref="WatchEvent"/> reports.</summary>
public enum WatchEventKind
{
    /// <summary>
    /// A tag's value differs from the last one reported; on the first successful cycle, every tag's value with no old
    /// value (<see cref="WatchEvent.IsInitial"/>), so a subscriber starts with the full picture.
    /// </summary>
    Changed,

    /// <summary>
    /// A cycle failed (the link, the PLC, or a value that does not decode): reported once, when the outage begins, with
    /// the exception. The watch goes on trying every retry interval.
    /// </summary>
    Outage,

    /// <summary>The first successful cycle after an outage; the changes since the last values reported follow.</summary>
    Resumed,

    /// <summary>
    /// A cycle took longer than the interval (the read, plus the subscriber's handling of its events). The next cycle
    /// starts at once; missed cycles are not made up.
    /// </summary>
    Overrun,

    /// <summary>
    /// A cycle read every tag (only with <see cref="WatchOptions.ReportEveryCycle"/>): reported after the cycle's
    /// changes, whether or not there were any, with the time the read took.
    /// </summary>
    Polled,

    /// <summary>
    /// Another failed try during an outage (only with <see cref="WatchOptions.ReportEveryCycle"/>; the first failure is
    /// the <see cref="Outage"/>), with the exception and the wait before the next try.
    /// </summary>
    RetryFailed,

    /// <summary>
    /// The watched unit did not answer <see cref="WatchOptions.DemoteAfter"/> cycles in a row and is demoted: no read
    /// for <see cref="WatchOptions.DemotionPeriod"/> (<see cref="WatchEvent.RetryDelay"/>), then one presence probe
    /// decides whether it is read again. Reported once per demotion, with the last failure; a probe that finds the unit
    /// still silent is a <see cref="RetryFailed"/>, and the first successful cycle after it a <see cref="Resumed"/>.
    /// </summary>
    Demoted,

    /// <summary>
    /// The reads the watch makes each cycle (only with <see cref="WatchOptions.ReportPlans"/>): reported before the
    /// first cycle, and again before a cycle that reads otherwise because a unit's model became known (MM) or a unit
    /// refused QQ (<see cref="HostLinkClientOptions.UseCompoundRead"/>); the plan is in <see cref="WatchEvent.Plan"/>.
    /// </summary>
    Planned,
}
