using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Statistics;

/// <summary>
/// What a technician reads about a link or one PLC unit on it, counted since the gateway started: the payload of the
/// retained statistics topics.
/// </summary>
internal sealed class UnitStatistics
{
    /// <summary>The link's configured name.</summary>
    [JsonPropertyName("link")]
    public required string Link { get; init; }

    /// <summary>The unit number; null for the link's totals.</summary>
    [JsonPropertyName("unit")]
    [JsonIgnore(Condition = JsonIgnoreCondition.WhenWritingNull)]
    public int? Unit { get; init; }

    /// <summary><c>online</c>, <c>comm-error</c> or <c>demoted</c> for a unit; the link's state for the totals.</summary>
    [JsonPropertyName("state")]
    public required string State { get; init; }

    /// <summary>Whether the unit is demoted now (for the totals: whether any unit is).</summary>
    [JsonPropertyName("demoted")]
    public bool Demoted { get; init; }

    /// <summary>How often the unit (for the totals: any unit) has been demoted.</summary>
    [JsonPropertyName("demotions")]
    public long Demotions { get; init; }

    /// <summary>Commands sent and finished, whatever their outcome (reads and writes; not presence probes).</summary>
    [JsonPropertyName("transactions")]
    public long Transactions { get; init; }

    /// <summary>Commands that failed after their retries, all kinds together.</summary>
    [JsonPropertyName("failures")]
    public long Failures { get; init; }

    /// <summary>Failed commands by kind (the <c>error.type</c> of the library's metrics: <c>timeout</c>, <c>frame_error</c>, <c>connection</c>, an end code's name…).</summary>
    [JsonPropertyName("failuresByKind")]
    public required IReadOnlyDictionary<string, long> FailuresByKind { get; init; }

    /// <summary>Attempts repeated after a timeout or a damaged frame.</summary>
    [JsonPropertyName("retries")]
    public long Retries { get; init; }

    /// <summary>The response time of the last command answered: its answered attempt, first frame out to last frame in, in ms; null before any.</summary>
    [JsonPropertyName("lastResponseMs")]
    public double? LastResponseMs { get; init; }

    /// <summary>The average response time of the commands answered, in ms; null before any.</summary>
    [JsonPropertyName("averageResponseMs")]
    public double? AverageResponseMs { get; init; }

    /// <summary>The unit's scan classes (for the totals: every unit's), by unit and interval: plan and measured cycle times.</summary>
    [JsonPropertyName("scanClasses")]
    public IReadOnlyList<ScanClassStatistics> ScanClasses { get; init; } = [];

    /// <summary>When the counting started (the gateway's start).</summary>
    [JsonPropertyName("since")]
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Since { get; init; }

    /// <summary>When these figures were taken.</summary>
    [JsonPropertyName("time")]
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }
}
