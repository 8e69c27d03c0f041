using Google.Protobuf;
using OmronHostLink.Gateway.Sparkplug.Wire;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The payloads an edge node sends (specification 3.0, 6.4.x): births name every metric with its alias, type and
/// value; data messages carry aliases only; deaths carry no metrics but the node's <c>bdSeq</c>.
/// </summary>
internal static class SparkplugPayloads
{
    /// <summary>The node metric that tells a host application which NDEATH ends which NBIRTH.</summary>
    public const string BirthDeathSequence = "bdSeq";

    /// <summary>The node metric a host application sets to true to ask for new births.</summary>
    public const string Rebirth = "Node Control/Rebirth";

    /// <summary>NBIRTH: seq 0, the bdSeq of this session and <c>Node Control/Rebirth</c>, then any node metrics.</summary>
    public static byte[] NodeBirth(ulong bdSeq, DateTimeOffset time, IEnumerable<(SparkplugMetric Metric, object? Value)>? nodeMetrics = null)
    {
        var payload = new Payload { Timestamp = SparkplugValues.Timestamp(time), Seq = 0 };
        payload.Metrics.Add(new Payload.Types.Metric { Name = BirthDeathSequence, Datatype = (uint)SparkplugDataType.Int64, LongValue = bdSeq, Timestamp = SparkplugValues.Timestamp(time) });
        payload.Metrics.Add(new Payload.Types.Metric { Name = Rebirth, Datatype = (uint)SparkplugDataType.Boolean, BooleanValue = false, Timestamp = SparkplugValues.Timestamp(time) });
        foreach ((SparkplugMetric metric, object? value) in nodeMetrics ?? [])
        {
            payload.Metrics.Add(Birth(metric, value, time, null));
        }

        return payload.ToByteArray();
    }

    /// <summary>NDEATH, registered as the MQTT will: the bdSeq of the birth it ends, no seq.</summary>
    public static byte[] NodeDeath(ulong bdSeq)
    {
        var payload = new Payload();
        payload.Metrics.Add(new Payload.Types.Metric { Name = BirthDeathSequence, Datatype = (uint)SparkplugDataType.Int64, LongValue = bdSeq });
        return payload.ToByteArray();
    }

    /// <summary>DBIRTH: every metric of the device with name, alias, type, value (null where none was read) and quality.</summary>
    public static byte[] DeviceBirth(ulong seq, DateTimeOffset time, IEnumerable<SparkplugMetricValue> metrics)
    {
        var payload = new Payload { Timestamp = SparkplugValues.Timestamp(time), Seq = seq };
        foreach (SparkplugMetricValue m in metrics)
        {
            payload.Metrics.Add(Birth(m.Metric, m.Value, m.Time, m.Quality));
        }

        return payload.ToByteArray();
    }

    /// <summary>
    /// DDATA or NDATA: the metrics that changed, by alias, with their read time and a quality where not good. The data
    /// type is repeated (the specification makes it optional after the birth) so that a reader without the birth's
    /// alias table, Eclipse Tahu's JavaScript decoder among them, still reads the value.
    /// </summary>
    public static byte[] Data(ulong seq, DateTimeOffset time, IEnumerable<SparkplugMetricValue> metrics)
    {
        var payload = new Payload { Timestamp = SparkplugValues.Timestamp(time), Seq = seq };
        foreach (SparkplugMetricValue m in metrics)
        {
            var metric = new Payload.Types.Metric { Alias = m.Metric.Alias, Datatype = (uint)m.Metric.DataType, Timestamp = SparkplugValues.Timestamp(m.Time) };
            Fill(metric, m.Metric.DataType, m.Value, m.Quality);
            payload.Metrics.Add(metric);
        }

        return payload.ToByteArray();
    }

    /// <summary>DDEATH: the device's metrics are stale until its next birth.</summary>
    public static byte[] DeviceDeath(ulong seq, DateTimeOffset time)
        => new Payload { Timestamp = SparkplugValues.Timestamp(time), Seq = seq }.ToByteArray();

    /// <summary>Reads a payload (a command); null when the bytes are not one.</summary>
    internal static Payload? TryParse(ReadOnlySpan<byte> bytes)
    {
        try
        {
            return Payload.Parser.ParseFrom(bytes);
        }
        catch (InvalidProtocolBufferException)
        {
            return null;
        }
    }

    private static Payload.Types.Metric Birth(SparkplugMetric m, object? value, DateTimeOffset time, int? quality)
    {
        var metric = new Payload.Types.Metric
        {
            Name = m.Name,
            Alias = m.Alias,
            Datatype = (uint)m.DataType,
            Timestamp = SparkplugValues.Timestamp(time),
        };
        Fill(metric, m.DataType, value, quality);
        return metric;
    }

    private static void Fill(Payload.Types.Metric metric, SparkplugDataType type, object? value, int? quality)
    {
        if (value is null)
        {
            metric.IsNull = true;
        }
        else
        {
            SparkplugValues.SetValue(metric, type, value);
        }

        if (quality is { } q && q != SparkplugQuality.Good)
        {
            metric.Properties = new Payload.Types.PropertySet();
            metric.Properties.Keys.Add(SparkplugQuality.PropertyName);
            metric.Properties.Values.Add(new Payload.Types.PropertyValue { Type = (uint)SparkplugDataType.Int32, IntValue = unchecked((uint)q) });
        }
    }
}
