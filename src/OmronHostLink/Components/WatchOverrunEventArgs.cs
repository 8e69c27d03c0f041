namespace OmronHostLink;

/// <summary>
/// A watch cycle took longer than the interval: the read, plus the handlers of its events (a slow handler slows the
/// polling rather than letting events queue up). The next cycle starts at once; missed cycles are not made up.
/// </summary>
public sealed class WatchOverrunEventArgs : EventArgs
{
    /// <summary>Creates the event's data.</summary>
    /// <param name="cycleTime">How long the cycle took.</param>
    /// <param name="timestamp">When the watch noticed.</param>
    public WatchOverrunEventArgs(TimeSpan cycleTime, DateTimeOffset timestamp)
    {
        CycleTime = cycleTime;
        Timestamp = timestamp;
    }

    /// <summary>How long the cycle took.</summary>
    public TimeSpan CycleTime { get; }

    /// <summary>When the watch noticed.</summary>
    public DateTimeOffset Timestamp { get; }
}
