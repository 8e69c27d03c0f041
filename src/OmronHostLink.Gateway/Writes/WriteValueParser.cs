using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Gateway.Writes;

/// <summary>
/// The value of a write command, JSON, as the words to write: the JSON is read here (a number, a string, true/false,
/// or an array of them for a tag of several values) and the words are laid out by the core's <see cref="PlcValueCodec"/>.
/// </summary>
internal static class WriteValueParser
{
    /// <summary>The smallest positive normal IEEE 754 single (2^-126); below it a REAL loses significant digits.</summary>
    private const float SmallestNormalSingle = 1.17549435E-38f;

    /// <summary>The smallest positive normal IEEE 754 double (2^-1022).</summary>
    private const double SmallestNormalDouble = 2.2250738585072014E-308;
    /// <summary>
    /// Reads the value of a write command for a tag and turns it into the words to write (for <c>bit</c>: one word,
    /// 0 or 1). Nothing is sent for a value this refuses.
    /// </summary>
    /// <param name="type">The tag's type.</param>
    /// <param name="count">The tag's count (characters for <c>string</c>).</param>
    /// <param name="value">The JSON value: a number, a string, true/false, or an array of <paramref name="count"/> of them.</param>
    /// <param name="order">Word order of 32-bit values.</param>
    /// <param name="words">The words to write.</param>
    /// <param name="error">Why the value is refused, in the user's words.</param>
    public static bool TryEncode(PlcValueType type, int count, JsonElement value, WordOrder order, out ushort[] words, out string error)
    {
        words = [];
        error = "";
        if (type == PlcValueType.String)
        {
            if (value.ValueKind != JsonValueKind.String)
            {
                error = $"a string tag takes a JSON string of at most {count} ASCII characters; got {Describe(value)}.";
                return false;
            }

            string text = value.GetString()!;
            if (text.Length > count)
            {
                error = $"the text has {text.Length} characters; the tag holds at most {count}.";
                return false;
            }

            foreach (char c in text)
            {
                if (c > '\x7F' || c == '\0')
                {
                    error = $"the text holds '{(c == '\0' ? "\\0" : c.ToString())}' (U+{(int)c:X4}); a PLC string takes ASCII characters U+0001–U+007F only.";
                    return false;
                }
            }

            // The whole tag is written, NUL-padded, so no tail of a longer old text remains.
            words = new ushort[PlcValueCodec.WordCount(PlcValueType.String, count)];
            PlcValueCodec.Encode(PlcValue.FromString(text), words);
            return true;
        }

        JsonElement[] items;
        if (count == 1)
        {
            items = [value];
        }
        else
        {
            if (value.ValueKind != JsonValueKind.Array || value.GetArrayLength() != count)
            {
                error = $"the tag has {count} values: send a JSON array of {count}; got {Describe(value)}.";
                return false;
            }

            items = value.EnumerateArray().ToArray();
        }

        int per = PlcValueCodec.WordCount(type);
        var result = new ushort[per * count];
        for (int i = 0; i < items.Length; i++)
        {
            string at = count == 1 ? "" : $"item {i}: ";
            if (!TryEncodeOne(type, items[i], order, result.AsSpan(i * per, per), out string why))
            {
                error = at + why;
                return false;
            }
        }

        words = result;
        return true;
    }

    private static bool TryEncodeOne(PlcValueType type, JsonElement item, WordOrder order, Span<ushort> dest, out string error)
    {
        if (type == PlcValueType.Bit)
        {
            // A bit is written to its bit address; the one word carries 0 or 1.
            bool? bit = item.ValueKind switch
            {
                JsonValueKind.True => true,
                JsonValueKind.False => false,
                JsonValueKind.Number when item.TryGetInt32(out int n) && n is 0 or 1 => n == 1,
                _ => null,
            };
            if (bit is null)
            {
                error = $"a bit takes true or false (or 1 or 0); got {Describe(item)}.";
                return false;
            }

            dest[0] = bit.Value ? (ushort)1 : (ushort)0;
            error = "";
            return true;
        }

        if (!TryValue(type, item, out PlcValue value, out error))
        {
            return false;
        }

        PlcValueCodec.Encode(value, dest, order);
        return true;
    }

    private static bool TryValue(PlcValueType type, JsonElement item, out PlcValue value, out string error)
    {
        value = default;
        error = "";
        long n;
        switch (type)
        {
            case PlcValueType.Word or PlcValueType.UInt16:
                if (!TryInteger(item, type, 0, ushort.MaxValue, out n, out error))
                {
                    return false;
                }

                value = type == PlcValueType.Word ? PlcValue.FromWord((ushort)n) : PlcValue.FromUInt16((ushort)n);
                return true;

            case PlcValueType.Int16:
                if (!TryInteger(item, type, short.MinValue, short.MaxValue, out n, out error))
                {
                    return false;
                }

                value = PlcValue.FromInt16((short)n);
                return true;

            case PlcValueType.Bcd:
                if (!TryInteger(item, type, 0, PlcWords.MaxBcd, out n, out error))
                {
                    return false;
                }

                value = PlcValue.FromBcd((int)n);
                return true;

            case PlcValueType.Bcd32:
                if (!TryInteger(item, type, 0, PlcWords.MaxBcd32, out n, out error))
                {
                    return false;
                }

                value = PlcValue.FromBcd32((int)n);
                return true;

            case PlcValueType.Int32:
                if (!TryInteger(item, type, int.MinValue, int.MaxValue, out n, out error))
                {
                    return false;
                }

                value = PlcValue.FromInt32((int)n);
                return true;

            case PlcValueType.UInt32:
                if (!TryInteger(item, type, 0, uint.MaxValue, out n, out error))
                {
                    return false;
                }

                value = PlcValue.FromUInt32((uint)n);
                return true;

            case PlcValueType.Float:
                if (!TryReal(item, single: true, out double d))
                {
                    error = $"a float takes a JSON number within ±{Text(float.MaxValue)}, and 0 or at least ±{Text(SmallestNormalSingle)} in magnitude; got {Describe(item)}.";
                    return false;
                }

                value = PlcValue.FromSingle((float)d);
                return true;

            case PlcValueType.Double:
                if (!TryReal(item, single: false, out double dd))
                {
                    error = $"a double takes a JSON number within ±{Text(double.MaxValue)}, and 0 or at least ±{Text(SmallestNormalDouble)} in magnitude; got {Describe(item)}.";
                    return false;
                }

                value = PlcValue.FromDouble(dd);
                return true;

            default:
                error = $"type {type.Name()} cannot be written.";
                return false;
        }
    }

    /// <summary>
    /// A JSON number the real type holds as given: finite, within its range once rounded to it, and not so small that it
    /// would be stored as 0 or as a denormal with fewer significant digits (1e-50 to a float would silently become 0).
    /// </summary>
    private static bool TryReal(JsonElement item, bool single, out double value)
    {
        if (item.ValueKind != JsonValueKind.Number || !item.TryGetDouble(out value) || !double.IsFinite(value))
        {
            value = 0;
            return false;
        }

        double stored = single ? (float)value : value;
        double magnitude = Math.Abs(stored);
        if (double.IsInfinity(magnitude))
        {
            return false;
        }

        if (magnitude == 0)
        {
            // 0 as written, or a number so small that it rounds to 0 (1e-50 to a float, 1e-400 even to a double).
            return !HasNonZeroDigit(item.GetRawText());
        }

        return magnitude >= (single ? SmallestNormalSingle : SmallestNormalDouble);
    }

    private static bool HasNonZeroDigit(string number)
    {
        foreach (char c in number)
        {
            if (c is 'e' or 'E')
            {
                return false;
            }

            if (c is >= '1' and <= '9')
            {
                return true;
            }
        }

        return false;
    }

    private static string Text(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static string Text(float value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static bool TryInteger(JsonElement item, PlcValueType type, long min, long max, out long value, out string error)
    {
        value = 0;
        error = "";
        if (item.ValueKind == JsonValueKind.Number && item.TryGetInt64(out value) && value >= min && value <= max)
        {
            return true;
        }

        error = $"{type.Name()} takes a whole number from {min.ToString(CultureInfo.InvariantCulture)} to {max.ToString(CultureInfo.InvariantCulture)}; got {Describe(item)}.";
        return false;
    }

    private static string Describe(JsonElement value)
    {
        string raw = value.GetRawText();
        return raw.Length > 40 ? raw.Substring(0, 40) + "…" : raw;
    }
}
