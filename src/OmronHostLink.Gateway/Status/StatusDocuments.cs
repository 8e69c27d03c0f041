using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

// The JSON documents the page reads (StatusJsonContext writes them, camelCase, nulls left out).

/// <summary>The Lines view: every enabled link with its units and scan classes.</summary>
internal sealed class LinesDocument
{
    /// <summary>When the figures were taken (the page's clock may differ).</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Now { get; init; }

    /// <summary>The links, by name.</summary>
    public required IReadOnlyList<LinkView> Links { get; init; }
}

/// <summary>A link in the Lines view: where it goes, its state and its figures since the gateway started.</summary>
internal sealed class LinkView
{
    /// <summary>The link's configured name.</summary>
    public required string Name { get; init; }

    /// <summary><c>online</c>, <c>comm-error</c> or <c>offline</c>.</summary>
    public required string State { get; init; }

    /// <summary>Since when it is in that state.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Since { get; init; }

    /// <summary>Why, for a state other than online.</summary>
    public string? Detail { get; init; }

    /// <summary>Where it goes: a serial port, or a serial-device server's <c>host:port</c>.</summary>
    public required string Endpoint { get; init; }

    /// <summary>The line's speed and format: <c>9600 bps 7E2</c>.</summary>
    public required string Line { get; init; }

    /// <summary><c>CMode</c> or <c>Fins</c>.</summary>
    public required string CommandSet { get; init; }

    /// <summary>Transactions per second over the last few seconds; null until two samples are apart.</summary>
    public double? TransactionsPerSecond { get; init; }

    /// <summary>The link's totals (every unit's figures added).</summary>
    public required Statistics.UnitStatistics Totals { get; init; }

    /// <summary>The PLC units polled on the link.</summary>
    public required IReadOnlyList<UnitView> Units { get; init; }

    /// <summary>The groups by interval: each scan class with its groups.</summary>
    public required IReadOnlyList<ScanClassView> ScanClasses { get; init; }
}

/// <summary>A PLC unit in the Lines view.</summary>
internal sealed class UnitView
{
    /// <summary>The unit number, 0–31.</summary>
    public required int Unit { get; init; }

    /// <summary><c>online</c>, <c>comm-error</c> or <c>demoted</c>.</summary>
    public required string State { get; init; }

    /// <summary>Since when it is in that state.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Since { get; init; }

    /// <summary>The last error, in words: why it stopped answering, or which group's read failed and why.</summary>
    public string? LastError { get; init; }

    /// <summary>When the last error happened.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? LastErrorTime { get; init; }

    /// <summary>Its figures since the gateway started.</summary>
    public required Statistics.UnitStatistics Figures { get; init; }

    /// <summary>Its last changes of state, oldest first.</summary>
    public required IReadOnlyList<UnitEventView> Events { get; init; }
}

/// <summary>A change of a unit's state.</summary>
internal sealed class UnitEventView
{
    /// <summary>When.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }

    /// <summary>The new state: <c>online</c>, <c>comm-error</c> or <c>demoted</c>.</summary>
    public required string State { get; init; }

    /// <summary>Why.</summary>
    public string? Detail { get; init; }
}

/// <summary>A scan class of a link: the groups of one unit polled at one interval.</summary>
internal sealed class ScanClassView
{
    /// <summary>The unit.</summary>
    public required int Unit { get; init; }

    /// <summary>The configured interval, in ms.</summary>
    public required double IntervalMs { get; init; }

    /// <summary>The groups (tags) of the class.</summary>
    public required IReadOnlyList<string> Groups { get; init; }

    /// <summary>The last cycle's time (from its start to its last answer), in ms; null before the first cycle.</summary>
    public double? MeasuredCycleMs { get; init; }

    /// <summary>The average cycle time, in ms; null before the first cycle.</summary>
    public double? AverageCycleMs { get; init; }

    /// <summary>The cycle the plan expects on the line the class shares with the link's others, in ms; null before the class is planned.</summary>
    public double? EstimatedCycleMs { get; init; }

    /// <summary>The commands a cycle, as planned; null before the class is planned.</summary>
    public int? Reads { get; init; }

    /// <summary>Cycles that ended after the next was due.</summary>
    public long Overruns { get; init; }
}

/// <summary>A tag in the Tags view: in the first document every field, afterwards what changed.</summary>
internal sealed class TagRow
{
    /// <summary>The tag's index, which later updates refer to.</summary>
    [JsonPropertyName("i")]
    public required int Index { get; init; }

    /// <summary>The link's name.</summary>
    public string? Link { get; init; }

    /// <summary>The unit.</summary>
    public int? Unit { get; init; }

    /// <summary>The tag's (poll group's) name.</summary>
    public string? Name { get; init; }

    /// <summary>Its first address.</summary>
    public string? Address { get; init; }

    /// <summary>Its type: word, bcd, int16, …</summary>
    public string? Type { get; init; }

    /// <summary>How many values.</summary>
    public int? Count { get; init; }

    /// <summary>Its poll interval, in ms.</summary>
    public double? IntervalMs { get; init; }

    /// <summary>Its recent numeric values, oldest first (one a refresh interval at most).</summary>
    public double[]? History { get; init; }

    /// <summary>The last value read: a number, a string, a bool or an array of them; null before the first read.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public object? Value { get; init; }

    /// <summary><c>good</c>, <c>stale</c> or <c>comm-error</c>; null before the first outcome.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public string? Quality { get; init; }

    /// <summary>When the last outcome came.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }

    /// <summary>When the value was last read.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? ReadTime { get; init; }

    /// <summary>Why the value is not good; null when it is.</summary>
    [JsonIgnore(Condition = JsonIgnoreCondition.Never)]
    public string? Error { get; init; }
}

/// <summary>An update of the Tags view: every tag (the first), or the tags that changed since the last.</summary>
internal sealed class TagsDocument
{
    /// <summary>When the update was made.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Now { get; init; }

    /// <summary>The tags.</summary>
    public required IReadOnlyList<TagRow> Tags { get; init; }
}

/// <summary>The Outputs view.</summary>
internal sealed class OutputsDocument
{
    /// <summary>When the states were taken.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Now { get; init; }

    /// <summary>Every configured output; empty when the gateway only logs.</summary>
    public required IReadOnlyList<OutputStatus> Outputs { get; init; }
}

/// <summary>An update of the Line trace view: the frames after the page's last.</summary>
internal sealed class TraceDocument
{
    /// <summary>The link.</summary>
    public required string Link { get; init; }

    /// <summary>Frames that were captured after the page's last one but are no longer kept (too many at once).</summary>
    public long Lost { get; init; }

    /// <summary>The frames, oldest first.</summary>
    public required IReadOnlyList<TraceFrameView> Frames { get; init; }
}

/// <summary>A frame in the Line trace view, explained as <c>hostlink explain</c> does.</summary>
internal sealed class TraceFrameView
{
    /// <summary>Its number in the link's trace (the page asks for the frames after the last it has).</summary>
    public required long Seq { get; init; }

    /// <summary>When the link sent it or took it, UTC, to the microsecond.</summary>
    public required string Time { get; init; }

    /// <summary><c>out</c> (to the PLC) or <c>in</c> (from the PLC).</summary>
    public required string Dir { get; init; }

    /// <summary>The unit: the frame's own, or its exchange's for a later frame; null when neither is known.</summary>
    public int? Unit { get; init; }

    /// <summary>The command's header (<c>RD</c>, <c>FA</c>): the frame's own, or its exchange's.</summary>
    public string? Header { get; init; }

    /// <summary>What the frame is (<c>DM AREA READ</c>, <c>FINS 0101 MEMORY AREA READ</c>).</summary>
    public string? Name { get; init; }

    /// <summary>An answer's end code.</summary>
    public string? EndCode { get; init; }

    /// <summary>The end code's meaning.</summary>
    public string? EndCodeMeaning { get; init; }

    /// <summary>For a frame from the PLC: the time since the link's last frame out, in ms.</summary>
    public double? LatencyMs { get; init; }

    /// <summary>The frame as text (CR as <c>\r</c>).</summary>
    public required string Text { get; init; }

    /// <summary>Its decoded fields, <c>name: value</c>.</summary>
    public required IReadOnlyList<string> Fields { get; init; }

    /// <summary>What is worth knowing about it.</summary>
    public required IReadOnlyList<string> Notes { get; init; }

    /// <summary>What is wrong with it.</summary>
    public required IReadOnlyList<string> Problems { get; init; }
}
