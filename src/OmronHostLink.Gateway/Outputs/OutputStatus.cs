namespace OmronHostLink.Gateway.Outputs;

/// <summary>How an output stands at one moment (<see cref="IOutputStatus"/>).</summary>
internal sealed record OutputStatus
{
    /// <summary>The output's name: <c>MQTT</c>, <c>Sparkplug B</c>.</summary>
    public required string Name { get; init; }

    /// <summary>Whether it is connected to its broker now.</summary>
    public required bool Connected { get; init; }

    /// <summary>Its state in words: <c>connected</c>, <c>online</c>, <c>waiting for primary host scada1</c>, <c>broker unreachable</c>.</summary>
    public required string State { get; init; }

    /// <summary>The broker in use (<c>host:port</c>).</summary>
    public required string Server { get; init; }

    /// <summary>Since when it is connected; null while it is not.</summary>
    public DateTimeOffset? ConnectedSince { get; init; }

    /// <summary>Why the last connection attempt failed or the last connection ended; null when none has.</summary>
    public string? LastError { get; init; }

    /// <summary>When it failed.</summary>
    public DateTimeOffset? LastErrorTime { get; init; }

    /// <summary>Messages waiting for the broker, the one in flight included; null for an output that keeps no queue.</summary>
    public long? QueueDepth { get; init; }

    /// <summary>Messages taken and not yet acknowledged by the broker; null for an output that keeps no queue.</summary>
    public long? Unsent { get; init; }

    /// <summary>Of the unsent messages, those a crash would lose now (held in memory only); null for an output that keeps no queue.</summary>
    public long? AtRisk { get; init; }

    /// <summary>When the broker last took a message; null before the first.</summary>
    public DateTimeOffset? LastPublish { get; init; }

    /// <summary>What else identifies it: the topic prefix and client id, the group and edge node ids.</summary>
    public string? Detail { get; init; }
}
