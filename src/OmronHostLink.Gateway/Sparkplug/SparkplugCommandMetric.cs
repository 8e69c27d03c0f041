using System.Text.Json;
using OmronHostLink.Gateway.Sparkplug.Wire;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>A metric of a received command (NCMD, DCMD): the metric it names and the value it carries.</summary>
internal sealed class SparkplugCommandMetric
{
    private readonly Payload.Types.Metric _metric;

    internal SparkplugCommandMetric(Payload.Types.Metric metric) => _metric = metric;

    /// <summary>The metric's name, when the command names it.</summary>
    public string? Name => _metric.HasName ? _metric.Name : null;

    /// <summary>The metric's alias, when the command uses it.</summary>
    public ulong? Alias => _metric.HasAlias ? _metric.Alias : null;

    /// <summary>
    /// The value as JSON (a number, true/false or a string) for a metric of <paramref name="type"/> — the type its birth
    /// declared — so that it goes through the same validation as a JSON write.
    /// </summary>
    /// <returns>False, with the reason, when the command carries no value or not in the field the type travels in.</returns>
    public bool TryGetValue(SparkplugDataType type, out JsonElement value, out string error)
        => SparkplugValues.TryReadAsJson(_metric, type, out value, out error);

    /// <summary>Reads a command payload; null when the bytes are not a Sparkplug B payload.</summary>
    public static IReadOnlyList<SparkplugCommandMetric>? Parse(ReadOnlySpan<byte> payload)
        => SparkplugPayloads.TryParse(payload) is { } parsed ? parsed.Metrics.Select(m => new SparkplugCommandMetric(m)).ToList() : null;
}
