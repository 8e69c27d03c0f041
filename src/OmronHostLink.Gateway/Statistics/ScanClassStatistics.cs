using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Statistics;

/// <summary>
/// One scan class of a PLC unit — its tags read together at one interval — in the statistics topics: the plan's reads,
/// its own time on the line and the cycle expected on the shared line, beside the cycle times measured.
/// </summary>
internal sealed class ScanClassStatistics
{
    /// <summary>The unit number.</summary>
    [JsonPropertyName("unit")]
    public int Unit { get; init; }

    /// <summary>The interval, in ms.</summary>
    [JsonPropertyName("intervalMs")]
    public double IntervalMs { get; init; }

    /// <summary>The tags (poll groups and tag-file rows) of the class.</summary>
    [JsonPropertyName("tags")]
    public int Tags { get; init; }

    /// <summary>The commands a cycle, as planned.</summary>
    [JsonPropertyName("reads")]
    public int Reads { get; init; }

    /// <summary>The characters on the line a cycle, both ways, as planned.</summary>
    [JsonPropertyName("characters")]
    public int Characters { get; init; }

    /// <summary>The class's own time on the line a cycle (its characters at the line's speed, and the send interval before each command), in ms.</summary>
    [JsonPropertyName("lineTimeMs")]
    public double LineTimeMs { get; init; }

    /// <summary>The cycle the plan expects on the line the class shares with the link's other classes (its own time on the line and its waits for theirs), in ms.</summary>
    [JsonPropertyName("estimatedCycleMs")]
    public double EstimatedCycleMs { get; init; }

    /// <summary>Cycles read since the gateway started.</summary>
    [JsonPropertyName("cycles")]
    public long Cycles { get; init; }

    /// <summary>The last cycle's time, from its start to its last answer (waits for the line included), in ms; null before the first.</summary>
    [JsonPropertyName("lastCycleMs")]
    public double? LastCycleMs { get; init; }

    /// <summary>The average cycle time, in ms; null before the first.</summary>
    [JsonPropertyName("averageCycleMs")]
    public double? AverageCycleMs { get; init; }

    /// <summary>Cycles that ended after the next was due (the next started late).</summary>
    [JsonPropertyName("overruns")]
    public long Overruns { get; init; }
}
