namespace OmronHostLink;

/// <summary>A watch's read failed: the PLC or the link is away. Raised once per outage; the watch keeps trying.</summary>
public sealed class ConnectionLostEventArgs : EventArgs
{
    /// <summary>Creates the event's data.</summary>
    /// <param name="exception">Why the read failed.</param>
    /// <param name="timestamp">When the watch noticed.</param>
    /// <param name="retryDelay">How long until the next try.</param>
    public ConnectionLostEventArgs(Exception exception, DateTimeOffset timestamp, TimeSpan retryDelay)
    {
        Exception = Guard.NotNull(exception);
        Timestamp = timestamp;
        RetryDelay = retryDelay;
    }

    /// <summary>
    /// Why the read failed: a <see cref="HostLinkTimeoutException"/>, <see cref="HostLinkConnectionException"/>,
    /// <see cref="HostLinkEndCodeException"/> or the like (see <see cref="HostLinkException.IsTransient"/>).
    /// </summary>
    public Exception Exception { get; }

    /// <summary>When the watch noticed.</summary>
    public DateTimeOffset Timestamp { get; }

    /// <summary>How long until the next try.</summary>
    public TimeSpan RetryDelay { get; }
}
