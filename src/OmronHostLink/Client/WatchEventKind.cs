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
}
