namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>A metric's value at a time: what a birth or a data message carries for it.</summary>
/// <param name="Metric">The metric.</param>
/// <param name="Value">The value (a number, bool or string); null where none was ever read.</param>
/// <param name="Time">When the value was read from the PLC (or when reading failed).</param>
/// <param name="Quality">A <see cref="SparkplugQuality"/> code.</param>
internal sealed record SparkplugMetricValue(SparkplugMetric Metric, object? Value, DateTimeOffset Time, int Quality = SparkplugQuality.Good);
