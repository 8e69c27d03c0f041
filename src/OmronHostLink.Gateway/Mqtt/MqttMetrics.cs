using System.Diagnostics.Metrics;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The MQTT output's instruments on the gateway's meter (<see cref="GatewayNames.Meter"/>).
/// </summary>
internal sealed class MqttMetrics
{
    private readonly Counter<long> _dropped;
    private readonly Counter<long> _published;
    private readonly Counter<long> _connections;
    private readonly Counter<long> _writes;

    /// <summary>Creates the instruments; the queue length is observed from <paramref name="queue"/>.</summary>
    public MqttMetrics(IMeterFactory meterFactory, OutboundQueue queue)
    {
        ArgumentNullException.ThrowIfNull(meterFactory);
        ArgumentNullException.ThrowIfNull(queue);
        Meter meter = meterFactory.Create(GatewayNames.Meter);
        _dropped = meter.CreateCounter<long>("hostlink.gateway.mqtt.dropped", "{message}", "Messages dropped because the outbound queue was full (the oldest go first).");
        _published = meter.CreateCounter<long>("hostlink.gateway.mqtt.published", "{message}", "Messages the broker acknowledged (QoS 1/2) or that were sent (QoS 0).");
        _connections = meter.CreateCounter<long>("hostlink.gateway.mqtt.connections", "{connection}", "Connections made to the broker.");
        _writes = meter.CreateCounter<long>("hostlink.gateway.mqtt.writes", "{command}", "Write commands by result: done, refused, failed.");
        meter.CreateObservableGauge("hostlink.gateway.mqtt.queue.length", () => queue.Count, "{message}", "Messages waiting for the broker.");
        queue.Dropped += n => _dropped.Add(n);
    }

    /// <summary>Counts a message the broker took.</summary>
    public void Published() => _published.Add(1);

    /// <summary>Counts a connection.</summary>
    public void Connected() => _connections.Add(1);

    /// <summary>Counts a write command by its result.</summary>
    public void Write(string result) => _writes.Add(1, new KeyValuePair<string, object?>("result", result));
}
