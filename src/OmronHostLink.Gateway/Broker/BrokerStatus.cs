namespace OmronHostLink.Gateway.Broker;

/// <summary>Where a broker connection stands.</summary>
internal enum BrokerState
{
    /// <summary>Not started yet.</summary>
    Starting,

    /// <summary>An attempt to connect is under way.</summary>
    Connecting,

    /// <summary>Connected to <see cref="BrokerStatus.Server"/>.</summary>
    Connected,

    /// <summary>Waiting before the next attempt (after a failure, a lost connection or a session ended on purpose).</summary>
    Waiting,

    /// <summary>Stopped with the gateway.</summary>
    Stopped,
}

/// <summary>
/// What an output adds to its connection's status: the state of its session in its own words (<c>online</c>,
/// <c>waiting for the primary host</c>) and its own figures (births, rebirths requested, stored changes…).
/// </summary>
/// <param name="State">The session's state.</param>
/// <param name="Figures">Counts by name, since the gateway started unless the name says otherwise.</param>
internal sealed record BrokerSession(string State, IReadOnlyDictionary<string, long> Figures);

/// <summary>
/// A read-only snapshot of a broker connection (<see cref="MqttBrokerConnection.Status"/>), for the statistics, a status
/// page and the tests.
/// </summary>
/// <param name="Output">The output that owns the connection: <c>mqtt</c> or <c>sparkplug</c>.</param>
/// <param name="ClientId">The MQTT client id it connects with.</param>
/// <param name="State">Where it stands.</param>
/// <param name="Server">The server in use, or tried next: <c>host:port</c>.</param>
/// <param name="ServerKey">That server's configuration key (<c>Mqtt</c>, <c>Mqtt:Servers:1</c>).</param>
/// <param name="ServerNumber">That server's place in the list, from 1.</param>
/// <param name="Servers">Every server of the list, in order (<c>host:port</c>).</param>
/// <param name="ConnectedSince">When the current connection was made; null while not connected.</param>
/// <param name="Connections">Connections made since the gateway started.</param>
/// <param name="FailedAttempts">Attempts failed since the last connection.</param>
/// <param name="LastProblem">Why the last connection failed or ended; null before any.</param>
/// <param name="LastProblemAt">When; null before any.</param>
/// <param name="DuplicateIdentity">Whether another client is taking this client id's sessions over (until a connection lasts).</param>
/// <param name="Session">What the output adds; null before it says anything.</param>
internal sealed record BrokerStatus(
    string Output,
    string ClientId,
    BrokerState State,
    string Server,
    string ServerKey,
    int ServerNumber,
    IReadOnlyList<string> Servers,
    DateTimeOffset? ConnectedSince,
    long Connections,
    int FailedAttempts,
    string? LastProblem,
    DateTimeOffset? LastProblemAt,
    bool DuplicateIdentity,
    BrokerSession? Session);
