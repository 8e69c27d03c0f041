using System.Globalization;
using OmronHostLink.Planning;

namespace OmronHostLink.Com;

/// <summary>
/// Values between the library's types and the ones VB6, VBA and VBScript hold: Long (32-bit), Single, Double, Boolean,
/// String, and arrays as a Variant holding an array of Variants (the only kind VBScript can index).
/// </summary>
internal static class ComValues
{
    /// <summary>A library value as a VB value: words and 16/32-bit integers as Long, unsigned 32-bit as Double.</summary>
    public static object From(object value) => value switch
    {
        ushort word => (int)word,
        short number => (int)number,
        uint number => (double)number,
        _ => value,
    };

    /// <summary>An array of values as a Variant array.</summary>
    public static object[] Array<T>(IReadOnlyList<T> values, Func<T, object> convert)
    {
        var result = new object[values.Count];
        for (int i = 0; i < values.Count; i++)
        {
            result[i] = convert(values[i]);
        }

        return result;
    }

    /// <summary>
    /// A word from a VB number: 0-65535, or -32768 to -1 for the same 16 bits as a VB Integer holds them.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">Outside -32768 to 65535.</exception>
    public static ushort Word(long value, string name)
        => value is >= short.MinValue and <= ushort.MaxValue
            ? unchecked((ushort)value)
            : throw new ArgumentOutOfRangeException(name, value, $"A word is 0 to 65535 (or -32768 to -1 for the same bits); {value.ToString(CultureInfo.InvariantCulture)} is neither.");

    /// <summary>
    /// The elements of a value VB passes as an array: a Variant array (<c>Array(1, 2, 3)</c>), a typed array
    /// (<c>Dim w(2) As Long</c>), or one value alone; a multi-dimensional array is refused.
    /// </summary>
    /// <exception cref="ArgumentException">The value is empty, or an array of more than one dimension.</exception>
    public static object[] Elements(object? value, string name)
    {
        switch (value)
        {
            case null or DBNull:
                throw new ArgumentException($"{name} is empty; pass an array (Array(1, 2, 3)) or one value.", name);
            case string:
                return [value];
            case System.Array array when array.Rank != 1:
                throw new ArgumentException($"{name} has {array.Rank} dimensions; pass a one-dimensional array.", name);
            case System.Array array:
                var items = new object[array.Length];
                int i = 0;
                foreach (object? item in array)
                {
                    items[i++] = item ?? throw new ArgumentException($"{name}({i - 1 + array.GetLowerBound(0)}) is empty.", name);
                }

                return items;
            default:
                return [value];
        }
    }

    /// <summary>A VB number as a long: Integer, Long, Single, Double, Currency, a numeric String; fractions refused.</summary>
    /// <exception cref="ArgumentException">Not a whole number.</exception>
    public static long WholeNumber(object value, string name)
    {
        try
        {
            double number = Convert.ToDouble(value, CultureInfo.InvariantCulture);
            if (number != Math.Floor(number) || double.IsInfinity(number) || Math.Abs(number) > long.MaxValue)
            {
                throw new ArgumentException($"{name} is {Text(value)}; a whole number is needed.", name);
            }

            return (long)number;
        }
        catch (Exception e) when (e is FormatException or InvalidCastException or OverflowException)
        {
            throw new ArgumentException($"{name} is {Text(value)}; a number is needed.", name, e);
        }
    }

    /// <summary>The texts of tags VB passes: one String or an array of Strings.</summary>
    public static string[] Tags(object? value, string name)
    {
        object[] items = Elements(value, name);
        var tags = new string[items.Length];
        for (int i = 0; i < items.Length; i++)
        {
            tags[i] = items[i] as string ?? throw new ArgumentException($"{name}({i}) is {Text(items[i])}; a tag is text such as D100 or D100:float.", name);
        }

        return tags;
    }

    /// <summary>PROGRAM, MONITOR or RUN.</summary>
    public static string ModeName(PlcMode mode) => mode switch
    {
        PlcMode.Program => "PROGRAM",
        PlcMode.Monitor => "MONITOR",
        _ => "RUN",
    };

    /// <summary>The mode named by <paramref name="text"/>, in any case.</summary>
    /// <exception cref="ArgumentException">Not PROGRAM, MONITOR or RUN.</exception>
    public static PlcMode Mode(string? text) => text?.Trim().ToUpperInvariant() switch
    {
        "PROGRAM" => PlcMode.Program,
        "MONITOR" => PlcMode.Monitor,
        "RUN" => PlcMode.Run,
        _ => throw new ArgumentException($"'{text}' is not a mode; use PROGRAM, MONITOR or RUN.", nameof(text)),
    };

    /// <summary>Writes <paramref name="value"/> as the tag's type says.</summary>
    public static void Write(IHostLinkUnit unit, PlcTag tag, object? value)
    {
        const string name = "value";
        if (value is null or DBNull)
        {
            throw new ArgumentException($"The value for {tag.Address} is empty.", name);
        }

        string address = tag.Address.ToString();
        switch (tag.Type)
        {
            case PlcValueType.Bit:
                unit.WriteBit(address, Convert.ToBoolean(value, CultureInfo.InvariantCulture));
                break;
            case PlcValueType.Word or PlcValueType.UInt16:
                unit.WriteWord(address, Word(WholeNumber(value, name), name));
                break;
            case PlcValueType.Int16:
                unit.Write(address, checked((short)WholeNumber(value, name)));
                break;
            case PlcValueType.Int32:
                unit.Write(address, checked((int)WholeNumber(value, name)));
                break;
            case PlcValueType.UInt32:
                unit.Write(address, checked((uint)WholeNumber(value, name)));
                break;
            case PlcValueType.Bcd:
                unit.Write(address, new Bcd16(checked((int)WholeNumber(value, name))));
                break;
            case PlcValueType.Bcd32:
                unit.Write(address, new Bcd32(checked((int)WholeNumber(value, name))));
                break;
            case PlcValueType.Float:
                unit.Write(address, Convert.ToSingle(value, CultureInfo.InvariantCulture));
                break;
            default:
                unit.Write(address, Convert.ToDouble(value, CultureInfo.InvariantCulture));
                break;
        }
    }

    private static string Text(object? value) => value switch
    {
        null => "Empty",
        string s => "\"" + s + "\"",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture) ?? value.GetType().Name,
    };
}
