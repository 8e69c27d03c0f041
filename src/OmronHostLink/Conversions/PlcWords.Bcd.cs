using System.Globalization;

namespace OmronHostLink;

// BCD: each hex digit of the word is one decimal digit, as timers, counters and many settings store numbers (1234 ↔ 0x1234).
public static partial class PlcWords
{
    /// <summary>The largest value one BCD word holds.</summary>
    public const int MaxBcd = 9999;

    /// <summary>The largest value two BCD words hold.</summary>
    public const int MaxBcd32 = 99_999_999;

    /// <summary>Encodes 0–9999 as a BCD word: 1234 → 0x1234.</summary>
    /// <param name="value">0–9999.</param>
    /// <returns>The BCD word.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 9999.</exception>
    public static ushort ToBcd(int value)
    {
        CheckBcdRange(value, MaxBcd, "one BCD word");
        return (ushort)EncodeBcd((uint)value);
    }

    /// <summary>Decodes a BCD word: 0x1234 → 1234.</summary>
    /// <param name="word">The word.</param>
    /// <returns>0–9999.</returns>
    /// <exception cref="FormatException">A digit of the word is A–F (e.g. 0x12A4), so it is not BCD.</exception>
    public static int FromBcd(ushort word) => DecodeBcd(word, 4);

    /// <summary>Decodes a BCD word as <see cref="FromBcd"/> does, without throwing.</summary>
    /// <returns>False when a digit of the word is A–F.</returns>
    internal static bool TryFromBcd(ushort word, out int value) => TryDecodeBcd(word, 4, out value);

    /// <summary>Encodes 0–99999999 as 8 BCD digits: 12345678 → 0x12345678.</summary>
    /// <param name="value">0–99999999.</param>
    /// <returns>The BCD digits as a 32-bit value.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    public static uint ToBcd32(int value)
    {
        CheckBcdRange(value, MaxBcd32, "two BCD words");
        return EncodeBcd((uint)value);
    }

    /// <summary>Decodes 8 BCD digits: 0x12345678 → 12345678.</summary>
    /// <param name="value">The BCD digits as a 32-bit value.</param>
    /// <returns>0–99999999.</returns>
    /// <exception cref="FormatException">A digit is A–F, so the value is not BCD.</exception>
    public static int FromBcd32(uint value) => DecodeBcd(value, 8);

    /// <summary>Decodes 8 BCD digits as <see cref="FromBcd32"/> does, without throwing.</summary>
    /// <returns>False when a digit is A–F.</returns>
    internal static bool TryFromBcd32(uint value, out int result) => TryDecodeBcd(value, 8, out result);

    /// <summary>Writes 0–99999999 as two BCD words: 12345678 → [0x5678, 0x1234] low word first.</summary>
    /// <param name="value">0–99999999.</param>
    /// <param name="dest">At least two words.</param>
    /// <param name="order">Which word receives the low four digits; Omron stores the low word first.</param>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="value"/> is negative or above 99999999.</exception>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than two words.</exception>
    public static void WriteBcd32(int value, Span<ushort> dest, WordOrder order = WordOrder.LowWordFirst) =>
        WriteUInt32(ToBcd32(value), dest, order);

    /// <summary>Reads two BCD words as one value: [0x5678, 0x1234] low word first → 12345678.</summary>
    /// <param name="words">At least two words.</param>
    /// <param name="order">Which word holds the low four digits; Omron stores the low word first.</param>
    /// <returns>0–99999999.</returns>
    /// <exception cref="ArgumentException"><paramref name="words"/> holds fewer than two words.</exception>
    /// <exception cref="FormatException">A digit is A–F, so the words are not BCD.</exception>
    public static int ReadBcd32(ReadOnlySpan<ushort> words, WordOrder order = WordOrder.LowWordFirst) =>
        FromBcd32(ReadUInt32(words, order));

    private static void CheckBcdRange(int value, int max, string holder)
    {
        if (value < 0 || value > max)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"{holder} can hold 0–{max}; {value} does not fit.");
        }
    }

    private static uint EncodeBcd(uint value)
    {
        uint result = 0;
        for (var shift = 0; value != 0; shift += 4, value /= 10)
        {
            result |= (value % 10) << shift;
        }

        return result;
    }

    private static int DecodeBcd(uint bcd, int digits)
    {
        if (TryDecodeBcd(bcd, digits, out var result))
        {
            return result;
        }

        var hex = bcd.ToString(digits == 4 ? "X4" : "X8", CultureInfo.InvariantCulture);
        var bad = hex.First(c => c > '9');
        throw new FormatException($"0x{hex} is not BCD: digit {bad} is not 0–9.");
    }

    private static bool TryDecodeBcd(uint bcd, int digits, out int value)
    {
        value = 0;
        for (var shift = (digits - 1) * 4; shift >= 0; shift -= 4)
        {
            var digit = (int)((bcd >> shift) & 0xF);
            if (digit > 9)
            {
                value = 0;
                return false;
            }

            value = (value * 10) + digit;
        }

        return true;
    }
}
