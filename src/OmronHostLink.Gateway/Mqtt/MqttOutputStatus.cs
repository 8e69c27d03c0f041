using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>How the MQTT JSON output stands: its broker connection, its outage queue and its last publish.</summary>
/// <param name="options">The validated <c>Mqtt</c> section.</param>
/// <param name="gateway">The output's connection and publisher.</param>
/// <param name="queue">The outage queue.</param>
/// <param name="store">What keeps the queue outside the process.</param>
internal sealed class MqttOutputStatus(IOptions<MqttOptions> options, MqttGateway gateway, OutboundQueue queue, OutboundQueueStore store) : IOutputStatus
{
    /// <inheritdoc/>
    public OutputStatus Status()
    {
        MqttOptions o = options.Value;
        bool connected = gateway.IsConnected;
        Broker.BrokerStatus broker = gateway.Connection.Status();
        (string Reason, DateTimeOffset Time)? failure = broker.LastProblem is { } problem && broker.LastProblemAt is { } at ? (problem, at) : null;
        long depth = queue.Count;
        return new OutputStatus
        {
            Name = "MQTT",
            Connected = connected,
            State = connected ? "connected" : failure is null ? "connecting" : "broker unreachable",
            Server = gateway.Connection.Broker,
            ConnectedSince = broker.ConnectedSince,
            LastError = failure?.Reason,
            LastErrorTime = failure?.Time,
            QueueDepth = depth,
            Unsent = depth,
            AtRisk = store.AtRisk(queue),
            LastPublish = gateway.Connection.LastPublished,
            Detail = $"client {o.ClientIdOrDefault}, topics {o.TopicPrefix}/…, {(store.IsDurable ? "durable queue" : "queue in memory")} of {queue.Capacity}",
        };
    }
}
