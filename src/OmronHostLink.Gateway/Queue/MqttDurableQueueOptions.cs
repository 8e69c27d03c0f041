using OmronHostLink.Gateway.Mqtt;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// The <c>Mqtt:DurableQueue</c> section: keep the outage queue on disk (SQLite, in <see cref="MqttOptions.StateDirectory"/>)
/// so that what waits for the broker survives the gateway's own crash or restart, and is sent in order on its next run.
/// </summary>
public sealed class MqttDurableQueueOptions
{
    /// <summary>Keep the queue on disk. Default false: the queue is in memory and a crash loses it (the next run announces how many).</summary>
    public bool Enabled { get; set; }

    /// <summary>The most the queued messages may take, in megabytes (1-1048576); beyond it the oldest are dropped. Default 256.</summary>
    public int MaxMegabytes { get; set; } = 256;

    /// <summary>How long a message may wait for the broker; older ones are dropped unsent. Default 168 h (a week).</summary>
    public TimeSpan MaxAge { get; set; } = TimeSpan.FromDays(7);
}
