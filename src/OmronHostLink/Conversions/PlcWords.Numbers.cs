namespace OmronHostLink;

// 16- and 32-bit binary values and IEEE 754 REAL.
public static partial class PlcWords
{
    /// <summary>Reads a word as a signed 16-bit value (INT): 0xFFFF → -1.</summary>
    /// <param name="word">The word.</param>
    /// <returns>The same bits as <see cref="short"/>.</returns>
    public static short ToInt16(ushort word) => unchecked((short)word);

    /// <summary>Makes the word for a signed 16-bit value (INT): -1 → 0xFFFF.</summary>
    /// <param name="value">The value.</param>
    /// <returns>The same bits as <see cref="ushort"/>.</returns>
    public static ushort FromInt16(short value) => unchecked((ushort)value);

    /// <summary>Reads an unsigned 32-bit value (UDINT) from the first two words.</summary>
    /// <param name="words">At least two words.</param>
    /// <param name="order">Which word holds the low 16 bits; Omron stores the low word first.</param>
    /// <returns>The value.</returns>
    /// <exception cref="ArgumentException"><paramref name="words"/> holds fewer than two words.</exception>
    public static uint ReadUInt32(ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst)
    {
        EnsureLength(words.Length, 2, nameof(words));
        CheckOrder(order);
        return order == WordOrder.LowWordFirst
            ? words[0] | ((uint)words[1] << 16)
            : words[1] | ((uint)words[0] << 16);
    }

    /// <summary>Writes an unsigned 32-bit value (UDINT) into the first two words.</summary>
    /// <param name="value">The value.</param>
    /// <param name="dest">At least two words.</param>
    /// <param name="order">Which word receives the low 16 bits; Omron stores the low word first.</param>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than two words.</exception>
    public static void WriteUInt32(uint value, Span<ushort> dest, WordOrder order = WordOrder.LowWordFirst)
    {
        EnsureLength(dest.Length, 2, nameof(dest));
        CheckOrder(order);
        var low = (ushort)value;
        var high = (ushort)(value >> 16);
        (dest[0], dest[1]) = order == WordOrder.LowWordFirst ? (low, high) : (high, low);
    }

    /// <summary>Reads a signed 32-bit value (DINT) from the first two words: [0xFFFE, 0xFFFF] low word first → -2.</summary>
    /// <param name="words">At least two words.</param>
    /// <param name="order">Which word holds the low 16 bits; Omron stores the low word first.</param>
    /// <returns>The value.</returns>
    /// <exception cref="ArgumentException"><paramref name="words"/> holds fewer than two words.</exception>
    public static int ReadInt32(ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst) =>
        unchecked((int)ReadUInt32(words, order));

    /// <summary>Writes a signed 32-bit value (DINT) into the first two words.</summary>
    /// <param name="value">The value.</param>
    /// <param name="dest">At least two words.</param>
    /// <param name="order">Which word receives the low 16 bits; Omron stores the low word first.</param>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than two words.</exception>
    public static void WriteInt32(int value, Span<ushort> dest, WordOrder order = WordOrder.LowWordFirst) =>
        WriteUInt32(unchecked((uint)value), dest, order);

    /// <summary>Reads an IEEE 754 single-precision value (REAL) from the first two words: [0x0000, 0x3F80] low word first → 1.0.</summary>
    /// <param name="words">At least two words.</param>
    /// <param name="order">Which word holds the low 16 bits; Omron stores the low word first.</param>
    /// <returns>The value; NaN and infinities come through as they are.</returns>
    /// <exception cref="ArgumentException"><paramref name="words"/> holds fewer than two words.</exception>
    public static float ReadSingle(ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst) =>
        SingleBits.ToSingle(ReadInt32(words, order));

    /// <summary>Writes an IEEE 754 single-precision value (REAL) into the first two words.</summary>
    /// <param name="value">The value.</param>
    /// <param name="dest">At least two words.</param>
    /// <param name="order">Which word receives the low 16 bits; Omron stores the low word first.</param>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than two words.</exception>
    public static void WriteSingle(float value, Span<ushort> dest, WordOrder order = WordOrder.LowWordFirst) =>
        WriteInt32(SingleBits.ToInt32(value), dest, order);

    /// <summary>Reads an IEEE 754 double-precision value (LREAL) from the first four words: [0, 0, 0, 0x3FF0] low word first → 1.0.</summary>
    /// <param name="words">At least four words.</param>
    /// <param name="order">Which end of the value the first word holds; Omron stores the low word first.</param>
    /// <returns>The value; NaN and infinities come through as they are.</returns>
    /// <exception cref="ArgumentException"><paramref name="words"/> holds fewer than four words.</exception>
    public static double ReadDouble(ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst)
    {
        EnsureLength(words.Length, 4, nameof(words));
        CheckOrder(order);
        ulong bits = 0;
        for (int i = 0; i < 4; i++)
        {
            ushort word = order == WordOrder.LowWordFirst ? words[i] : words[3 - i];
            bits |= (ulong)word << (16 * i);
        }

        return BitConverter.Int64BitsToDouble(unchecked((long)bits));
    }

    /// <summary>Writes an IEEE 754 double-precision value (LREAL) into the first four words.</summary>
    /// <param name="value">The value.</param>
    /// <param name="dest">At least four words.</param>
    /// <param name="order">Which end of the value the first word receives; Omron stores the low word first.</param>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than four words.</exception>
    public static void WriteDouble(double value, Span<ushort> dest, WordOrder order = WordOrder.LowWordFirst)
    {
        EnsureLength(dest.Length, 4, nameof(dest));
        CheckOrder(order);
        ulong bits = unchecked((ulong)BitConverter.DoubleToInt64Bits(value));
        for (int i = 0; i < 4; i++)
        {
            dest[order == WordOrder.LowWordFirst ? i : 3 - i] = (ushort)(bits >> (16 * i));
        }
    }
}
