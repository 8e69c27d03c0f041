using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// A host application's STATE payload (specification 3.0): UTF-8 JSON <c>{"online": true|false, "timestamp": ms}</c>,
/// the timestamp in milliseconds since the Unix epoch (UTC), the same in a host session's birth and in its will.
/// </summary>
/// <param name="Online">Whether the host application is online; null when the payload lacks it.</param>
/// <param name="Timestamp">When the host application's session began; null when the payload lacks it.</param>
internal sealed record SparkplugStatePayload(
    [property: JsonPropertyName("online")] bool? Online,
    [property: JsonPropertyName("timestamp")] long? Timestamp);
