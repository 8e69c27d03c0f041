namespace OmronHostLink;

// Bits within a word: bit 0 is the least significant, as in CIO100.00.
public static partial class PlcWords
{
    /// <summary>Whether bit <paramref name="bit"/> of <paramref name="word"/> is set.</summary>
    /// <param name="word">The word.</param>
    /// <param name="bit">0 (least significant) to 15.</param>
    /// <returns>The bit.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="bit"/> is not 0–15.</exception>
    public static bool GetBit(ushort word, int bit)
    {
        CheckBitNumber(bit);
        return (word & (1 << bit)) != 0;
    }

    /// <summary>Returns <paramref name="word"/> with bit <paramref name="bit"/> set or cleared.</summary>
    /// <param name="word">The word.</param>
    /// <param name="bit">0 (least significant) to 15.</param>
    /// <param name="value">The new state of the bit.</param>
    /// <returns>The changed word.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="bit"/> is not 0–15.</exception>
    public static ushort SetBit(ushort word, int bit, bool value)
    {
        CheckBitNumber(bit);
        return value ? (ushort)(word | (1 << bit)) : (ushort)(word & ~(1 << bit));
    }

    /// <summary>Splits a word into its 16 bits; element <c>n</c> is bit <c>n</c>.</summary>
    /// <param name="word">The word.</param>
    /// <returns>16 booleans.</returns>
    public static bool[] ToBits(ushort word)
    {
        var bits = new bool[16];
        ToBits(word, bits);
        return bits;
    }

    /// <summary>Writes the 16 bits of a word into <paramref name="dest"/>; element <c>n</c> is bit <c>n</c>.</summary>
    /// <param name="word">The word.</param>
    /// <param name="dest">At least 16 elements; only the first 16 are written.</param>
    /// <exception cref="ArgumentException"><paramref name="dest"/> holds fewer than 16 elements.</exception>
    public static void ToBits(ushort word, Span<bool> dest)
    {
        if (dest.Length < 16)
        {
            throw new ArgumentException($"16 elements are needed but the span holds {dest.Length}.", nameof(dest));
        }

        for (var bit = 0; bit < 16; bit++)
        {
            dest[bit] = (word & (1 << bit)) != 0;
        }
    }

    /// <summary>Builds a word from up to 16 bits; element <c>n</c> is bit <c>n</c>, missing bits are 0.</summary>
    /// <param name="bits">0–16 elements.</param>
    /// <returns>The word.</returns>
    /// <exception cref="ArgumentException"><paramref name="bits"/> holds more than 16 elements.</exception>
    public static ushort FromBits(ReadOnlySpan<bool> bits)
    {
        if (bits.Length > 16)
        {
            throw new ArgumentException($"A word holds 16 bits; the span holds {bits.Length}.", nameof(bits));
        }

        var word = 0;
        for (var bit = 0; bit < bits.Length; bit++)
        {
            if (bits[bit])
            {
                word |= 1 << bit;
            }
        }

        return (ushort)word;
    }

    private static void CheckBitNumber(int bit)
    {
        if ((uint)bit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, $"Bit {bit} does not exist; bits are 0–15.");
        }
    }
}
