namespace OmronHostLink;

/// <summary>
/// The one conversion between PLC words and typed values (<see cref="PlcValueType"/>): how many words values take,
/// decoding and encoding, with the word order of 32- and 64-bit values. Planned reads (<c>ReadTagsAsync</c>), the
/// console and the worker all convert through it.
/// </summary>
/// <remarks>
/// Layouts: a word, BCD, INT and UINT take one word; DINT, UDINT, REAL and 8-digit BCD two; LREAL four (Omron stores the low word
/// first, see <see cref="WordOrder"/>); text two ASCII characters a word, high byte first, ending at the first NUL; a
/// bit is bit <c>n</c> of a word, bit 0 the least significant.
/// </remarks>
public static class PlcValueCodec
{
    /// <summary>The number of words <paramref name="count"/> consecutive values take.</summary>
    /// <param name="type">The type.</param>
    /// <param name="count">The number of values; for <see cref="PlcValueType.String"/> the number of characters.</param>
    /// <param name="firstBit">For <see cref="PlcValueType.Bit"/>: the bit (0–15) of the first word that is the first value.</param>
    /// <returns>The number of words, counted from the word that holds the first value.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="count"/> is negative or <paramref name="firstBit"/> is not 0–15.</exception>
    public static int WordCount(PlcValueType type, int count = 1, int firstBit = 0)
    {
        if (count < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"A count cannot be negative; it was {count}.");
        }

        if ((uint)firstBit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(firstBit), firstBit, $"Bit {firstBit} does not exist; bits are 0–15.");
        }

        return type switch
        {
            PlcValueType.String => PlcWords.WordsForString(count),
            PlcValueType.Bit => (firstBit + count + 15) / 16,
            _ => checked(count * CheckType(type).WordsPerValue()),
        };
    }

    /// <summary>Decodes one value from the start of <paramref name="words"/>.</summary>
    /// <param name="type">The type.</param>
    /// <param name="words">The words; text runs to the first NUL or the last word.</param>
    /// <param name="order">How 32- and 64-bit values lie in their words.</param>
    /// <param name="bit">For <see cref="PlcValueType.Bit"/>: the bit, counted from bit 0 of the first word (16 is bit 0 of the second).</param>
    /// <returns>The value.</returns>
    /// <exception cref="ArgumentException">There are too few words for the type.</exception>
    /// <exception cref="FormatException">The words do not hold a value of the type: a BCD digit above 9, a text byte above 0x7F.</exception>
    public static PlcValue Decode(PlcValueType type, ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst, int bit = 0)
    {
        DecodeCore(type, words, order, bit, int.MaxValue, strict: true, out PlcValue value);
        return value;
    }

    /// <summary>Decodes one value as <see cref="Decode"/> does, but reports words that hold no value of the type instead of throwing.</summary>
    /// <returns>False when a BCD digit is above 9 or a text byte above 0x7F.</returns>
    /// <exception cref="ArgumentException">There are too few words for the type.</exception>
    public static bool TryDecode(PlcValueType type, ReadOnlySpan<ushort> words, WordOrder order, int bit, out PlcValue value)
        => DecodeCore(type, words, order, bit, int.MaxValue, strict: false, out value);

    /// <summary>
    /// Decodes <paramref name="count"/> consecutive values: each in its own words, bits one after another from
    /// <paramref name="firstBit"/> across words, and for <see cref="PlcValueType.String"/> one text of at most
    /// <paramref name="count"/> characters.
    /// </summary>
    /// <exception cref="ArgumentException">There are fewer words than <see cref="WordCount"/> says the values take.</exception>
    /// <exception cref="FormatException">A value's words do not hold a value of the type.</exception>
    public static PlcValue[] DecodeValues(PlcValueType type, ReadOnlySpan<ushort> words, int count, WordOrder order = WordOrder.LowWordFirst, int firstBit = 0)
    {
        int needed = WordCount(type, count, firstBit);
        if (words.Length < needed)
        {
            throw new ArgumentException($"{count} {type.Name()} values need {needed} words; {words.Length} were given.", nameof(words));
        }

        if (type == PlcValueType.String)
        {
            DecodeCore(type, words, order, 0, count, strict: true, out PlcValue text);
            return [text];
        }

        var values = new PlcValue[count];
        int per = type.WordsPerValue();
        for (int i = 0; i < count; i++)
        {
            values[i] = type == PlcValueType.Bit
                ? Decode(type, words, order, firstBit + i)
                : Decode(type, words.Slice(i * per, per), order);
        }

        return values;
    }

    /// <summary>Encodes <paramref name="value"/> into the first words of <paramref name="destination"/>.</summary>
    /// <returns>The number of words written.</returns>
    /// <exception cref="ArgumentException">
    /// <paramref name="destination"/> is too short, or the value is a bit (a bit is written to its bit address, not as a word).
    /// </exception>
    public static int Encode(PlcValue value, Span<ushort> destination, WordOrder order = WordOrder.LowWordFirst)
    {
        int needed = EncodedLength(value);
        if (destination.Length < needed)
        {
            throw new ArgumentException($"A {value.Type.Name()} value takes {needed} words; the span holds {destination.Length}.", nameof(destination));
        }

        switch (value.Type)
        {
            case PlcValueType.Word or PlcValueType.UInt16:
                destination[0] = value.ToUInt16();
                break;
            case PlcValueType.Int16:
                destination[0] = PlcWords.FromInt16(value.ToInt16());
                break;
            case PlcValueType.Bcd:
                destination[0] = PlcWords.ToBcd(value.ToInt32());
                break;
            case PlcValueType.Bcd32:
                PlcWords.WriteBcd32(value.ToInt32(), destination, order);
                break;
            case PlcValueType.Int32:
                PlcWords.WriteInt32(value.ToInt32(), destination, order);
                break;
            case PlcValueType.UInt32:
                PlcWords.WriteUInt32(value.ToUInt32(), destination, order);
                break;
            case PlcValueType.Float:
                PlcWords.WriteSingle(value.ToSingle(), destination, order);
                break;
            case PlcValueType.Double:
                PlcWords.WriteDouble(value.ToDouble(), destination, order);
                break;
            default:
                PlcWords.WriteString(value.ToString(), destination);
                break;
        }

        return needed;
    }

    /// <summary>Encodes values one after another into a new array.</summary>
    /// <exception cref="ArgumentException">A value is a bit.</exception>
    public static ushort[] Encode(IReadOnlyList<PlcValue> values, WordOrder order = WordOrder.LowWordFirst)
    {
        Guard.NotNull(values);
        int total = 0;
        foreach (PlcValue value in values)
        {
            total += EncodedLength(value);
        }

        var words = new ushort[total];
        int at = 0;
        foreach (PlcValue value in values)
        {
            at += Encode(value, words.AsSpan(at), order);
        }

        return words;
    }

    private static int EncodedLength(PlcValue value) => value.Type switch
    {
        PlcValueType.Bit => throw new ArgumentException("A bit is not encoded into a word; write it to its bit address.", nameof(value)),
        PlcValueType.String => PlcWords.WordsForString(value.ToString().Length),
        _ => value.Type.WordsPerValue(),
    };

    private static bool DecodeCore(PlcValueType type, ReadOnlySpan<ushort> words, WordOrder order, int bit, int maxLength, bool strict, out PlcValue value)
    {
        int needed = type switch
        {
            PlcValueType.String => 0,
            PlcValueType.Bit => bit < 0 ? throw new ArgumentOutOfRangeException(nameof(bit), bit, "A bit number cannot be negative.") : (bit / 16) + 1,
            _ => CheckType(type).WordsPerValue(),
        };
        if (words.Length < needed)
        {
            throw new ArgumentException($"A {type.Name()} value needs {needed} words; {words.Length} were given.", nameof(words));
        }

        switch (type)
        {
            case PlcValueType.Word:
                value = PlcValue.FromWord(words[0]);
                return true;
            case PlcValueType.UInt16:
                value = PlcValue.FromUInt16(words[0]);
                return true;
            case PlcValueType.Int16:
                value = PlcValue.FromInt16(PlcWords.ToInt16(words[0]));
                return true;
            case PlcValueType.Int32:
                value = PlcValue.FromInt32(PlcWords.ReadInt32(words, order));
                return true;
            case PlcValueType.UInt32:
                value = PlcValue.FromUInt32(PlcWords.ReadUInt32(words, order));
                return true;
            case PlcValueType.Float:
                value = PlcValue.FromSingle(PlcWords.ReadSingle(words, order));
                return true;
            case PlcValueType.Double:
                value = PlcValue.FromDouble(PlcWords.ReadDouble(words, order));
                return true;
            case PlcValueType.Bit:
                value = PlcValue.FromBit(PlcWords.GetBit(words[bit / 16], bit % 16));
                return true;
            case PlcValueType.Bcd:
                if (strict)
                {
                    value = PlcValue.FromBcd(PlcWords.FromBcd(words[0]));
                    return true;
                }

                bool bcd = PlcWords.TryFromBcd(words[0], out int number);
                value = bcd ? PlcValue.FromBcd(number) : default;
                return bcd;
            case PlcValueType.Bcd32:
                if (strict)
                {
                    value = PlcValue.FromBcd32(PlcWords.ReadBcd32(words, order));
                    return true;
                }

                bool bcd32 = PlcWords.TryFromBcd32(PlcWords.ReadUInt32(words, order), out int number32);
                value = bcd32 ? PlcValue.FromBcd32(number32) : default;
                return bcd32;
            default:
                if (strict)
                {
                    value = PlcValue.FromString(PlcWords.ReadString(words, maxLength));
                    return true;
                }

                bool ascii = PlcWords.TryReadString(words, maxLength, out string text, out _);
                value = ascii ? PlcValue.FromString(text) : default;
                return ascii;
        }
    }

    private static PlcValueType CheckType(PlcValueType type)
        => type is >= PlcValueType.Word and <= PlcValueType.Bcd32
            ? type
            : throw new ArgumentOutOfRangeException(nameof(type), type, $"{type} is not a PLC value type.");
}
