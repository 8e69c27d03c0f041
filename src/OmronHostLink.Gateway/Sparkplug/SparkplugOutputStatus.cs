using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// How the Sparkplug B edge node stands: its session and broker connection and its last publish. It keeps no queue:
/// what is read while it is offline reaches the host application in the births of the next session.
/// </summary>
/// <param name="node">The node's names and devices.</param>
/// <param name="edgeNode">The node's MQTT session.</param>
internal sealed class SparkplugOutputStatus(SparkplugNode node, SparkplugEdgeNode edgeNode) : IOutputStatus
{
    /// <inheritdoc/>
    public OutputStatus Status()
    {
        bool connected = edgeNode.Connection.Client.IsConnected;
        Broker.BrokerStatus broker = edgeNode.Connection.Status();
        (string Reason, DateTimeOffset Time)? failure = broker.LastProblem is { } problem && broker.LastProblemAt is { } at ? (problem, at) : null;
        string state = edgeNode.IsOnline ? "online (births sent)"
            : connected && edgeNode.PrimaryHostId is { } host ? $"connected, waiting for primary host {host} to be online"
            : connected ? "connected"
            : failure is null ? "connecting" : "broker unreachable";
        return new OutputStatus
        {
            Name = "Sparkplug B",
            Connected = connected,
            State = state,
            Server = edgeNode.Connection.Broker,
            ConnectedSince = broker.ConnectedSince,
            LastError = failure?.Reason,
            LastErrorTime = failure?.Time,
            LastPublish = edgeNode.Connection.LastPublished,
            Detail = $"group {node.GroupId}, edge node {node.EdgeNodeId}, {node.Devices.Count()} device(s)",
        };
    }
}
