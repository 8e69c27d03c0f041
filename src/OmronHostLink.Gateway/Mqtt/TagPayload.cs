using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The JSON published on a tag's topic (retained):
/// <c>{"value":1234,"type":"int16","quality":"good","time":"2025-01-31T08:00:00.125Z","address":"D100"}</c>.
/// </summary>
internal sealed class TagPayload
{
    /// <summary>The value: number, string, bool, or an array of them; null when never read.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public object? Value { get; init; }

    /// <summary>The tag's type name: word, bcd, int16, uint16, int32, uint32, float, string, bit.</summary>
    public required string Type { get; init; }

    /// <summary><c>good</c>, <c>stale</c> or <c>comm-error</c>.</summary>
    public required string Quality { get; init; }

    /// <summary>When the value was read from the PLC, UTC, ISO 8601 with milliseconds; null when never read.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }

    /// <summary>The first address, CX-Programmer style.</summary>
    public required string Address { get; init; }

    /// <summary>Why the value is not good; absent when it is.</summary>
    public string? Error { get; init; }
}
