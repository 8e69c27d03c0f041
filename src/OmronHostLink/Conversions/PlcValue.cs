using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// One value of a <see cref="PlcValueType"/>: what <see cref="PlcValueCodec"/> decodes from PLC words and encodes into
/// them. Numbers and bits are held without boxing. Two values are equal when their types and values are; REAL and LREAL
/// values compare their bits, so a NaN equals the same NaN and a change detector sees no change.
/// </summary>
public readonly struct PlcValue : IEquatable<PlcValue>
{
    // Integers as themselves, REAL and LREAL as their IEEE 754 bits, a bit as 0 or 1; text in _text.
    private readonly long _number;
    private readonly string? _text;

    private PlcValue(PlcValueType type, long number, string? text = null)
    {
        Type = type;
        _number = number;
        _text = text;
    }

    /// <summary>The type of the value.</summary>
    public PlcValueType Type { get; }

    /// <summary>A raw word.</summary>
    public static PlcValue FromWord(ushort value) => new(PlcValueType.Word, value);

    /// <summary>An unsigned 16-bit value (UINT).</summary>
    public static PlcValue FromUInt16(ushort value) => new(PlcValueType.UInt16, value);

    /// <summary>A signed 16-bit value (INT).</summary>
    public static PlcValue FromInt16(short value) => new(PlcValueType.Int16, value);

    /// <summary>A signed 32-bit value (DINT).</summary>
    public static PlcValue FromInt32(int value) => new(PlcValueType.Int32, value);

    /// <summary>An unsigned 32-bit value (UDINT).</summary>
    public static PlcValue FromUInt32(uint value) => new(PlcValueType.UInt32, value);

    /// <summary>A number 0–9999 stored as one BCD word.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 9999.</exception>
    public static PlcValue FromBcd(int value)
    {
        if (value < 0 || value > PlcWords.MaxBcd)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"one BCD word can hold 0–{PlcWords.MaxBcd}; {value} does not fit.");
        }

        return new(PlcValueType.Bcd, value);
    }

    /// <summary>A number 0–99999999 stored as 8 BCD digits in two words.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    public static PlcValue FromBcd32(int value)
    {
        if (value < 0 || value > PlcWords.MaxBcd32)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"two BCD words can hold 0–{PlcWords.MaxBcd32}; {value} does not fit.");
        }

        return new(PlcValueType.Bcd32, value);
    }

    /// <summary>An IEEE 754 single-precision value (REAL).</summary>
    public static PlcValue FromSingle(float value) => new(PlcValueType.Float, SingleBits.ToInt32(value));

    /// <summary>An IEEE 754 double-precision value (LREAL).</summary>
    public static PlcValue FromDouble(double value) => new(PlcValueType.Double, BitConverter.DoubleToInt64Bits(value));

    /// <summary>ASCII text.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is <see langword="null"/>.</exception>
    /// <exception cref="ArgumentException">The text holds a character outside ASCII.</exception>
    public static PlcValue FromString(string text)
    {
        Guard.NotNull(text);
        for (int i = 0; i < text.Length; i++)
        {
            if (text[i] > 0x7F)
            {
                throw new ArgumentException($"'{text[i]}' (U+{(int)text[i]:X4}) at position {i} is not ASCII; PLC text holds characters U+0000–U+007F only.", nameof(text));
            }
        }

        return new(PlcValueType.String, 0, text);
    }

    /// <summary>One bit.</summary>
    public static PlcValue FromBit(bool value) => new(PlcValueType.Bit, value ? 1 : 0);

    /// <summary>The value of a <see cref="PlcValueType.Word"/> or <see cref="PlcValueType.UInt16"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public ushort ToUInt16() => Type is PlcValueType.Word or PlcValueType.UInt16 ? (ushort)_number : throw Mismatch("a 16-bit word");

    /// <summary>The value of an <see cref="PlcValueType.Int16"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public short ToInt16() => Type == PlcValueType.Int16 ? (short)_number : throw Mismatch("int16");

    /// <summary>The value of an <see cref="PlcValueType.Int32"/>, a <see cref="PlcValueType.Bcd"/> word or a <see cref="PlcValueType.Bcd32"/> pair.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public int ToInt32() => Type is PlcValueType.Int32 or PlcValueType.Bcd or PlcValueType.Bcd32 ? (int)_number : throw Mismatch("int32, bcd or bcd32");

    /// <summary>The value of a <see cref="PlcValueType.UInt32"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public uint ToUInt32() => Type == PlcValueType.UInt32 ? (uint)_number : throw Mismatch("uint32");

    /// <summary>The value of a <see cref="PlcValueType.Float"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public float ToSingle() => Type == PlcValueType.Float ? SingleBits.ToSingle((int)_number) : throw Mismatch("float");

    /// <summary>The value of a <see cref="PlcValueType.Double"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public double ToDouble() => Type == PlcValueType.Double ? BitConverter.Int64BitsToDouble(_number) : throw Mismatch("double");

    /// <summary>The value of a <see cref="PlcValueType.Bit"/>.</summary>
    /// <exception cref="InvalidCastException">The value has another type.</exception>
    public bool ToBoolean() => Type == PlcValueType.Bit ? _number != 0 : throw Mismatch("bit");

    /// <summary>
    /// The value in its .NET type, boxed: <see cref="ushort"/> (Word, UInt16), <see cref="short"/> (Int16),
    /// <see cref="int"/> (Int32, Bcd, Bcd32), <see cref="uint"/> (UInt32), <see cref="float"/> (Float), <see cref="double"/>
    /// (Double), <see cref="string"/> (String) or <see cref="bool"/> (Bit).
    /// </summary>
    public object ToObject() => Type switch
    {
        PlcValueType.Word or PlcValueType.UInt16 => ToUInt16(),
        PlcValueType.Int16 => ToInt16(),
        PlcValueType.Int32 or PlcValueType.Bcd or PlcValueType.Bcd32 => ToInt32(),
        PlcValueType.UInt32 => ToUInt32(),
        PlcValueType.Float => ToSingle(),
        PlcValueType.Double => ToDouble(),
        PlcValueType.String => ToString(),
        _ => ToBoolean(),
    };

    /// <summary>
    /// The value in invariant text: a word as <c>0x04D2</c>, numbers in decimal, REAL and LREAL round-trippable, a bit as
    /// <c>1</c> or <c>0</c>, text as it is.
    /// </summary>
    public override string ToString() => Type switch
    {
        PlcValueType.Word => "0x" + ToUInt16().ToString("X4", CultureInfo.InvariantCulture),
        PlcValueType.Float => ToSingle().ToString("R", CultureInfo.InvariantCulture),
        PlcValueType.Double => ToDouble().ToString("R", CultureInfo.InvariantCulture),
        PlcValueType.String => _text ?? string.Empty,
        PlcValueType.Bit => ToBoolean() ? "1" : "0",
        _ => _number.ToString(CultureInfo.InvariantCulture),
    };

    /// <inheritdoc/>
    public bool Equals(PlcValue other) => Type == other.Type && _number == other._number && string.Equals(_text, other._text, StringComparison.Ordinal);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is PlcValue other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => ((int)Type * 397) ^ _number.GetHashCode() ^ (_text is null ? 0 : StringComparer.Ordinal.GetHashCode(_text));

    /// <summary>Whether two values have the same type and value.</summary>
    public static bool operator ==(PlcValue left, PlcValue right) => left.Equals(right);

    /// <summary>Whether two values differ in type or value.</summary>
    public static bool operator !=(PlcValue left, PlcValue right) => !left.Equals(right);

    private InvalidCastException Mismatch(string wanted) => new($"The value is a {Type.Name()} value, not {wanted}.");
}
