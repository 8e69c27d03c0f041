using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The payload of <c>{prefix}/status/{clientId}/outputs</c>: each MQTT output's broker connection — the server in use,
/// its state, connections, the last problem, a duplicate client id — and its own figures (the JSON queue; the Sparkplug
/// births, rebirths requested and store-and-forward).
/// </summary>
internal sealed class OutputsPayload
{
    /// <summary>One entry per output, in the order they were set up.</summary>
    public required IReadOnlyList<OutputPayload> Outputs { get; init; }

    /// <summary>When the figures were taken (UTC).</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public required DateTimeOffset? Time { get; init; }

    /// <summary>The payload of the connections' statuses at <paramref name="time"/>.</summary>
    public static OutputsPayload From(IEnumerable<BrokerStatus> statuses, DateTimeOffset time)
        => new() { Outputs = statuses.Select(OutputPayload.From).ToArray(), Time = time };
}

/// <summary>One output's broker connection and figures (<see cref="BrokerStatus"/>), as JSON.</summary>
internal sealed class OutputPayload
{
    /// <summary><c>mqtt</c> or <c>sparkplug</c>.</summary>
    public required string Output { get; init; }

    /// <summary>The MQTT client id.</summary>
    public required string ClientId { get; init; }

    /// <summary><c>connecting</c>, <c>connected</c>, <c>waiting</c> (between attempts) or <c>stopped</c>.</summary>
    public required string State { get; init; }

    /// <summary>The server in use, or tried next: <c>host:port</c>.</summary>
    public required string Server { get; init; }

    /// <summary>Its configuration key.</summary>
    public required string ServerKey { get; init; }

    /// <summary>Its place in the list, from 1.</summary>
    public required int ServerNumber { get; init; }

    /// <summary>The list, in order.</summary>
    public required IReadOnlyList<string> Servers { get; init; }

    /// <summary>When the current connection was made; absent while not connected.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? ConnectedSince { get; init; }

    /// <summary>Connections made since the gateway started.</summary>
    public required long Connections { get; init; }

    /// <summary>Attempts failed since the last connection.</summary>
    public required int FailedAttempts { get; init; }

    /// <summary>Why the last connection failed or ended; absent before any.</summary>
    public string? LastProblem { get; init; }

    /// <summary>When.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? LastProblemAt { get; init; }

    /// <summary>Whether another client is taking this client id's sessions over.</summary>
    public required bool DuplicateIdentity { get; init; }

    /// <summary>The output's session: <c>online</c>, <c>offline</c>, <c>waiting for the primary host</c>.</summary>
    public string? Session { get; init; }

    /// <summary>The output's own counts.</summary>
    public IReadOnlyDictionary<string, long>? Figures { get; init; }

    /// <summary>The payload of one status.</summary>
    public static OutputPayload From(BrokerStatus status)
    {
        ArgumentNullException.ThrowIfNull(status);
        return new OutputPayload
        {
            Output = status.Output,
            ClientId = status.ClientId,
            State = status.State.ToString().ToLowerInvariant(),
            Server = status.Server,
            ServerKey = status.ServerKey,
            ServerNumber = status.ServerNumber,
            Servers = status.Servers,
            ConnectedSince = status.ConnectedSince,
            Connections = status.Connections,
            FailedAttempts = status.FailedAttempts,
            LastProblem = status.LastProblem,
            LastProblemAt = status.LastProblemAt,
            DuplicateIdentity = status.DuplicateIdentity,
            Session = status.Session?.State,
            Figures = status.Session?.Figures,
        };
    }
}
