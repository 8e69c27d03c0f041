namespace OmronHostLink;

/// <summary>A watch read successfully again after an outage; the changes since follow as value-changed events.</summary>
public sealed class ConnectionRestoredEventArgs : EventArgs
{
    /// <summary>Creates the event's data.</summary>
    /// <param name="outage">How long the outage lasted.</param>
    /// <param name="timestamp">When the watch noticed.</param>
    public ConnectionRestoredEventArgs(TimeSpan outage, DateTimeOffset timestamp)
    {
        Outage = outage;
        Timestamp = timestamp;
    }

    /// <summary>How long the outage lasted.</summary>
    public TimeSpan Outage { get; }

    /// <summary>When the watch noticed.</summary>
    public DateTimeOffset Timestamp { get; }
}
