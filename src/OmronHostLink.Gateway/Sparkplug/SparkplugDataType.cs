namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The Sparkplug B data type numbers (specification 3.0, 6.4.16) that this gateway sends or accepts. A metric carries
/// the number in its <c>datatype</c> field; the number decides which <c>value</c> field holds the value.
/// </summary>
internal enum SparkplugDataType
{
    /// <summary>Not known.</summary>
    Unknown = 0,

    /// <summary>Signed 8-bit, in <c>int_value</c>.</summary>
    Int8 = 1,

    /// <summary>Signed 16-bit, two's complement in <c>int_value</c>.</summary>
    Int16 = 2,

    /// <summary>Signed 32-bit, two's complement in <c>int_value</c>.</summary>
    Int32 = 3,

    /// <summary>Signed 64-bit, two's complement in <c>long_value</c>.</summary>
    Int64 = 4,

    /// <summary>Unsigned 8-bit, in <c>int_value</c>.</summary>
    UInt8 = 5,

    /// <summary>Unsigned 16-bit, in <c>int_value</c>.</summary>
    UInt16 = 6,

    /// <summary>Unsigned 32-bit, in <c>long_value</c> as Eclipse Tahu's encoders send it (and <c>int_value</c> accepted).</summary>
    UInt32 = 7,

    /// <summary>Unsigned 64-bit, in <c>long_value</c>.</summary>
    UInt64 = 8,

    /// <summary>IEEE 754 single, in <c>float_value</c>.</summary>
    Float = 9,

    /// <summary>IEEE 754 double, in <c>double_value</c>.</summary>
    Double = 10,

    /// <summary>In <c>boolean_value</c>.</summary>
    Boolean = 11,

    /// <summary>UTF-8 text, in <c>string_value</c>.</summary>
    String = 12,

    /// <summary>Milliseconds since the Unix epoch (UTC), in <c>long_value</c>.</summary>
    DateTime = 13,

    /// <summary>Long text, in <c>string_value</c>.</summary>
    Text = 14,
}
