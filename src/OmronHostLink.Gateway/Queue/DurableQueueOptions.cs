namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// The durable outage queue (<c>Mqtt:DurableQueue</c>): keep the queue on disk (SQLite, in the state directory) so that
/// what waits for the broker survives the gateway's own crash or restart, and is sent in order on its next run.
/// </summary>
internal sealed class DurableQueueOptions
{
    /// <summary>Keep the queue on disk. Default false: the queue is in memory and a crash loses it (the next run announces how many).</summary>
    public bool Enabled { get; set; }

    /// <summary>The most the queued messages may take, in megabytes (1-1048576); beyond it the oldest are dropped. Default 256.</summary>
    public int MaxMegabytes { get; set; } = 256;

    /// <summary>How long a message may wait for the broker; older ones are dropped unsent. Default 168 h (a week).</summary>
    public TimeSpan MaxAge { get; set; } = TimeSpan.FromDays(7);
}
