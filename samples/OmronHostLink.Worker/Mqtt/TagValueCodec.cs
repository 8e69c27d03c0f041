using System.Globalization;
using System.Text.Json;

namespace OmronHostLink.Worker.Mqtt;

/// <summary>
/// A tag's words as typed values for JSON, and JSON values back to words for a write. One value is a scalar, several
/// an array: <c>word</c>/<c>uint16</c> → ushort, <c>int16</c> → short, <c>bcd</c> → int, <c>int32</c> → int,
/// <c>uint32</c> → uint, <c>float</c> → float, <c>string</c> → string, <c>bit</c> → bool.
/// </summary>
public static class TagValueCodec
{
    /// <summary>Decodes the words of a successful read.</summary>
    /// <param name="type">How the words are read.</param>
    /// <param name="address">The first address (its bit number for <c>bit</c>).</param>
    /// <param name="count">How many values (characters for <c>string</c>, bits for <c>bit</c>).</param>
    /// <param name="words">The words read; a timer/counter completion flag is one word, 0 or 1.</param>
    /// <param name="order">Word order of 32-bit values.</param>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9, or text bytes are not ASCII.</exception>
    public static object Decode(PlcValueType type, PlcAddress address, int count, ReadOnlySpan<ushort> words, WordOrder order)
    {
        if (type == PlcValueType.String)
        {
            string text = PlcWords.ReadString(words);
            return text.Length > count ? text.Substring(0, count) : text;
        }

        if (type == PlcValueType.Bit && address.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return words[0] != 0;
        }

        return type switch
        {
            PlcValueType.Word or PlcValueType.UInt16 => Values(count, words, static (w, i) => w[i]),
            PlcValueType.Int16 => Values(count, words, static (w, i) => PlcWords.ToInt16(w[i])),
            PlcValueType.Bcd => Values(count, words, static (w, i) => PlcWords.FromBcd(w[i])),
            PlcValueType.Int32 => Values(count, words, (w, i) => PlcWords.ReadInt32(w.Slice(2 * i, 2), order)),
            PlcValueType.UInt32 => Values(count, words, (w, i) => PlcWords.ReadUInt32(w.Slice(2 * i, 2), order)),
            PlcValueType.Float => Values(count, words, (w, i) => PlcWords.ReadSingle(w.Slice(2 * i, 2), order)),
            PlcValueType.Bit => Values(count, words, (w, i) => PlcWords.GetBit(w[(address.Bit + i) / 16], (address.Bit + i) % 16)),
            _ => throw new ArgumentOutOfRangeException(nameof(type), type, null),
        };
    }

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
            words = new ushort[PlcWords.WordsForString(count)];
            PlcWords.WriteString(text, words);
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

        int per = type.WordsPerValue();
        var result = new ushort[type == PlcValueType.Bit ? 1 : per * count];
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
        error = "";
        switch (type)
        {
            case PlcValueType.Bit:
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
                return true;

            case PlcValueType.Word or PlcValueType.UInt16:
                if (!TryInteger(item, type, 0, ushort.MaxValue, out long u16, out error))
                {
                    return false;
                }

                dest[0] = (ushort)u16;
                return true;

            case PlcValueType.Int16:
                if (!TryInteger(item, type, short.MinValue, short.MaxValue, out long i16, out error))
                {
                    return false;
                }

                dest[0] = PlcWords.FromInt16((short)i16);
                return true;

            case PlcValueType.Bcd:
                if (!TryInteger(item, type, 0, PlcWords.MaxBcd, out long bcd, out error))
                {
                    return false;
                }

                dest[0] = PlcWords.ToBcd((int)bcd);
                return true;

            case PlcValueType.Int32:
                if (!TryInteger(item, type, int.MinValue, int.MaxValue, out long i32, out error))
                {
                    return false;
                }

                PlcWords.WriteInt32((int)i32, dest, order);
                return true;

            case PlcValueType.UInt32:
                if (!TryInteger(item, type, 0, uint.MaxValue, out long u32, out error))
                {
                    return false;
                }

                PlcWords.WriteUInt32((uint)u32, dest, order);
                return true;

            case PlcValueType.Float:
                if (item.ValueKind != JsonValueKind.Number || !item.TryGetDouble(out double d)
                    || !float.IsFinite((float)d))
                {
                    error = $"a float takes a JSON number within ±{float.MaxValue.ToString("R", CultureInfo.InvariantCulture)}; got {Describe(item)}.";
                    return false;
                }

                PlcWords.WriteSingle((float)d, dest, order);
                return true;

            default:
                error = $"type {type.Name()} cannot be written.";
                return false;
        }
    }

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

    private static object Values<T>(int count, ReadOnlySpan<ushort> words, ValueReader<T> read)
    {
        if (count == 1)
        {
            return read(words, 0)!;
        }

        var values = new T[count];
        for (int i = 0; i < count; i++)
        {
            values[i] = read(words, i);
        }

        return values;
    }

    private delegate T ValueReader<out T>(ReadOnlySpan<ushort> words, int index);
}
