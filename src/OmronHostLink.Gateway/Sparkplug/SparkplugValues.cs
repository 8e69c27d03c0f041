using System.Globalization;
using System.Text.Json;
using OmronHostLink.Gateway.Sparkplug.Wire;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Tag types to Sparkplug data types, and values in and out of a metric's <c>value</c> field by the rules of the
/// specification (3.0, 6.4.16): signed integers travel as two's complement in the unsigned fields.
/// </summary>
internal static class SparkplugValues
{
    /// <summary>The Sparkplug data type of one value of a tag of <paramref name="type"/>.</summary>
    public static SparkplugDataType DataTypeOf(PlcValueType type) => type switch
    {
        PlcValueType.Word or PlcValueType.UInt16 or PlcValueType.Bcd => SparkplugDataType.UInt16,
        PlcValueType.Int16 => SparkplugDataType.Int16,
        PlcValueType.Int32 => SparkplugDataType.Int32,
        PlcValueType.UInt32 or PlcValueType.Bcd32 => SparkplugDataType.UInt32,
        PlcValueType.Float => SparkplugDataType.Float,
        PlcValueType.Double => SparkplugDataType.Double,
        PlcValueType.String => SparkplugDataType.String,
        PlcValueType.Bit => SparkplugDataType.Boolean,
        _ => throw new ArgumentOutOfRangeException(nameof(type), type, null),
    };

    /// <summary>Puts one value (as the tag codec decodes it: a number, a bool or a string) into the metric.</summary>
    /// <exception cref="ArgumentException">The value does not fit <paramref name="type"/>.</exception>
    internal static void SetValue(Payload.Types.Metric metric, SparkplugDataType type, object value)
    {
        switch (type)
        {
            case SparkplugDataType.Int8 or SparkplugDataType.Int16 or SparkplugDataType.Int32:
                metric.IntValue = unchecked((uint)Convert.ToInt32(value, CultureInfo.InvariantCulture));
                break;
            case SparkplugDataType.UInt8 or SparkplugDataType.UInt16:
                metric.IntValue = Convert.ToUInt32(value, CultureInfo.InvariantCulture);
                break;
            case SparkplugDataType.UInt32 or SparkplugDataType.UInt64:
                metric.LongValue = Convert.ToUInt64(value, CultureInfo.InvariantCulture);
                break;
            case SparkplugDataType.Int64:
                metric.LongValue = unchecked((ulong)Convert.ToInt64(value, CultureInfo.InvariantCulture));
                break;
            case SparkplugDataType.Float:
                metric.FloatValue = Convert.ToSingle(value, CultureInfo.InvariantCulture);
                break;
            case SparkplugDataType.Double:
                metric.DoubleValue = Convert.ToDouble(value, CultureInfo.InvariantCulture);
                break;
            case SparkplugDataType.Boolean:
                metric.BooleanValue = Convert.ToBoolean(value, CultureInfo.InvariantCulture);
                break;
            case SparkplugDataType.String or SparkplugDataType.Text:
                metric.StringValue = Convert.ToString(value, CultureInfo.InvariantCulture) ?? "";
                break;
            default:
                throw new ArgumentException($"Sparkplug data type {type} is not sent by this gateway.", nameof(type));
        }
    }

    /// <summary>
    /// Reads a command metric's value as JSON (a number, true/false or a string), so that a DCMD write goes through the
    /// same validation as a JSON write. The value field must be the one <paramref name="type"/> travels in.
    /// </summary>
    /// <returns>False, with the reason, when the metric carries no value or the wrong field.</returns>
    internal static bool TryReadAsJson(Payload.Types.Metric metric, SparkplugDataType type, out JsonElement value, out string error)
    {
        value = default;
        error = "";
        if (metric.HasIsNull && metric.IsNull)
        {
            error = "the metric is null; a write needs a value";
            return false;
        }

        string? json = (type, metric.ValueCase) switch
        {
            (SparkplugDataType.Int8 or SparkplugDataType.Int16 or SparkplugDataType.Int32, Payload.Types.Metric.ValueOneofCase.IntValue)
                => unchecked((int)metric.IntValue).ToString(CultureInfo.InvariantCulture),
            (SparkplugDataType.UInt8 or SparkplugDataType.UInt16 or SparkplugDataType.UInt32, Payload.Types.Metric.ValueOneofCase.IntValue)
                => metric.IntValue.ToString(CultureInfo.InvariantCulture),
            (SparkplugDataType.UInt32 or SparkplugDataType.UInt64, Payload.Types.Metric.ValueOneofCase.LongValue)
                => metric.LongValue.ToString(CultureInfo.InvariantCulture),
            (SparkplugDataType.Int64, Payload.Types.Metric.ValueOneofCase.LongValue)
                => unchecked((long)metric.LongValue).ToString(CultureInfo.InvariantCulture),
            (SparkplugDataType.Float, Payload.Types.Metric.ValueOneofCase.FloatValue) when float.IsFinite(metric.FloatValue)
                => metric.FloatValue.ToString("R", CultureInfo.InvariantCulture),
            (SparkplugDataType.Double, Payload.Types.Metric.ValueOneofCase.DoubleValue) when double.IsFinite(metric.DoubleValue)
                => metric.DoubleValue.ToString("R", CultureInfo.InvariantCulture),
            (SparkplugDataType.Boolean, Payload.Types.Metric.ValueOneofCase.BooleanValue)
                => metric.BooleanValue ? "true" : "false",
            (SparkplugDataType.String or SparkplugDataType.Text, Payload.Types.Metric.ValueOneofCase.StringValue)
                => JsonSerializer.Serialize(metric.StringValue, SparkplugJsonContext.Default.String),
            _ => null,
        };

        if (json is null)
        {
            error = metric.ValueCase == Payload.Types.Metric.ValueOneofCase.None
                ? "the metric carries no value"
                : $"a {type} metric's value travels in {FieldOf(type)}, not in {metric.ValueCase}";
            return false;
        }

        using JsonDocument document = JsonDocument.Parse(json);
        value = document.RootElement.Clone();
        return true;
    }

    private static string FieldOf(SparkplugDataType type) => type switch
    {
        SparkplugDataType.Int8 or SparkplugDataType.Int16 or SparkplugDataType.Int32 or SparkplugDataType.UInt8 or SparkplugDataType.UInt16 => "int_value",
        SparkplugDataType.UInt32 => "long_value or int_value",
        SparkplugDataType.Int64 or SparkplugDataType.UInt64 or SparkplugDataType.DateTime => "long_value",
        SparkplugDataType.Float => "float_value (a finite number)",
        SparkplugDataType.Double => "double_value (a finite number)",
        SparkplugDataType.Boolean => "boolean_value",
        _ => "string_value",
    };

    /// <summary>Milliseconds since the Unix epoch, as Sparkplug timestamps count.</summary>
    public static ulong Timestamp(DateTimeOffset time) => (ulong)time.ToUnixTimeMilliseconds();
}
