namespace OmronHostLink.Gateway.Queue;

/// <summary>A message waiting for the broker.</summary>
/// <param name="Topic">Where it goes.</param>
/// <param name="Payload">UTF-8 JSON, or plain text for the status topics.</param>
/// <param name="Retain">Whether the broker keeps it as the topic's last value.</param>
/// <param name="CorrelationData">MQTT 5 correlation data of a reply; null otherwise.</param>
internal sealed record OutboundMessage(string Topic, byte[] Payload, bool Retain, byte[]? CorrelationData = null)
{
    /// <summary>The order in which it was queued (set by the queue).</summary>
    public long Sequence { get; internal set; }

    /// <summary>When it was queued (set by the queue; kept by a durable journal across restarts).</summary>
    public DateTimeOffset QueuedAt { get; internal set; }

    /// <summary>Roughly what it costs to keep: topic, payload and correlation data, plus a row's overhead.</summary>
    internal long Size => 32L + Topic.Length + Payload.Length + (CorrelationData?.Length ?? 0);
}
