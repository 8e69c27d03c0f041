using System.Diagnostics.Metrics;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// The broker connections of this gateway (one per MQTT output), for what reads them all: the statistics, a status
/// page, and the gauge <c>hostlink.gateway.broker.server</c> — 1 for the server each output is connected to, 0 for the
/// other servers of its list, attributed with the output (<c>hostlink.output</c>: <c>mqtt</c>, <c>sparkplug</c>) and
/// the server (<c>server.address</c>, <c>server.port</c>).
/// </summary>
internal sealed class BrokerConnections
{
    /// <summary>The gauge of the server in use.</summary>
    public const string ServerGaugeName = "hostlink.gateway.broker.server";

    private readonly List<MqttBrokerConnection> _connections = [];

    /// <summary>Creates the registry and its gauge on the gateway's meter.</summary>
    public BrokerConnections(IMeterFactory meterFactory)
    {
        ArgumentNullException.ThrowIfNull(meterFactory);
        meterFactory.Create(GatewayNames.Meter).CreateObservableGauge(
            ServerGaugeName,
            Observe,
            "{connection}",
            "1 for the broker an output is connected to, 0 for the other servers of its list.");
    }

    /// <summary>A connection's state changed (connected, ended, another server).</summary>
    public event Action? Changed;

    /// <summary>The connections, in the order the outputs added them.</summary>
    public IReadOnlyList<MqttBrokerConnection> All
    {
        get
        {
            lock (_connections)
            {
                return _connections.ToArray();
            }
        }
    }

    /// <summary>A snapshot of every connection.</summary>
    public IReadOnlyList<BrokerStatus> Statuses() => All.Select(c => c.Status()).ToArray();

    /// <summary>Adds an output's connection.</summary>
    public void Add(MqttBrokerConnection connection)
    {
        ArgumentNullException.ThrowIfNull(connection);
        lock (_connections)
        {
            _connections.Add(connection);
        }

        connection.Changed += () => Changed?.Invoke();
    }

    private IEnumerable<Measurement<int>> Observe()
    {
        foreach (MqttBrokerConnection connection in All)
        {
            BrokerStatus status = connection.Status();
            foreach (MqttServer server in connection.Servers)
            {
                bool inUse = status.State == BrokerState.Connected && server.Index == status.ServerNumber - 1;
                yield return new Measurement<int>(
                    inUse ? 1 : 0,
                    new KeyValuePair<string, object?>("hostlink.output", status.Output),
                    new KeyValuePair<string, object?>("server.address", server.Host),
                    new KeyValuePair<string, object?>("server.port", server.Port));
            }
        }
    }
}
