using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// What a gateway announces at start on <c>{prefix}/status/{clientId}/lost</c> when its previous run ended with
/// messages the broker had not acknowledged and no durable queue kept them: <c>{"lost":42,"time":"…"}</c>.
/// </summary>
internal sealed class LostMessagesPayload
{
    /// <summary>How many messages (value and status changes, write replies) may have been lost; some may have arrived.</summary>
    public required long Lost { get; init; }

    /// <summary>When this run announced it, UTC.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }
}
