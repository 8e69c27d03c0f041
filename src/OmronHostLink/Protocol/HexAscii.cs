namespace OmronHostLink.Protocol;

/// <summary>
/// ASCII encodings used inside Host Link frames: hexadecimal bytes and words, and fixed-width decimal (BCD-style) fields.
/// Output is always upper case, as every Omron unit writes it; input accepts either case.
/// </summary>
internal static class HexAscii
{
    private static ReadOnlySpan<byte> Digits => "0123456789ABCDEF"u8;

    /// <summary>The upper-case hex character for a value 0-15.</summary>
    public static byte Nibble(int value) => Digits[value & 0xF];

    /// <summary>Writes <paramref name="value"/> as two hex characters.</summary>
    public static void WriteByte(byte value, Span<byte> destination)
    {
        destination[1] = Digits[value & 0xF];
        destination[0] = Digits[value >> 4];
    }

    /// <summary>Writes <paramref name="value"/> as four hex characters, most significant first.</summary>
    public static void WriteWord(ushort value, Span<byte> destination)
    {
        destination[3] = Digits[value & 0xF];
        destination[2] = Digits[(value >> 4) & 0xF];
        destination[1] = Digits[(value >> 8) & 0xF];
        destination[0] = Digits[value >> 12];
    }

    /// <summary>Writes each word as four hex characters; <paramref name="destination"/> must hold 4 × words.</summary>
    public static void WriteWords(ReadOnlySpan<ushort> words, Span<byte> destination)
    {
        for (int i = 0; i < words.Length; i++)
        {
            WriteWord(words[i], destination.Slice(i * 4, 4));
        }
    }

    /// <summary>Writes a non-negative number as exactly <paramref name="destination"/>.Length decimal digits.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The number is negative or needs more digits.</exception>
    public static void WriteDecimal(int value, Span<byte> destination)
    {
        if (value < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, "A decimal field cannot be negative.");
        }

        int v = value;
        for (int i = destination.Length - 1; i >= 0; i--)
        {
            destination[i] = (byte)('0' + (v % 10));
            v /= 10;
        }

        if (v != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, $"{value} does not fit in {destination.Length} decimal digits.");
        }
    }

    /// <summary>Parses one hex character.</summary>
    public static bool TryParseNibble(byte c, out int value)
    {
        if (c >= '0' && c <= '9')
        {
            value = c - '0';
            return true;
        }

        int lower = c | 0x20;
        if (lower >= 'a' && lower <= 'f')
        {
            value = lower - 'a' + 10;
            return true;
        }

        value = 0;
        return false;
    }

    /// <summary>Parses exactly two hex characters.</summary>
    public static bool TryParseByte(ReadOnlySpan<byte> text, out byte value)
    {
        if (text.Length == 2 && TryParseNibble(text[0], out int hi) && TryParseNibble(text[1], out int lo))
        {
            value = (byte)((hi << 4) | lo);
            return true;
        }

        value = 0;
        return false;
    }

    /// <summary>Parses exactly four hex characters.</summary>
    public static bool TryParseWord(ReadOnlySpan<byte> text, out ushort value)
    {
        int result = 0;
        if (text.Length != 4)
        {
            value = 0;
            return false;
        }

        for (int i = 0; i < 4; i++)
        {
            if (!TryParseNibble(text[i], out int n))
            {
                value = 0;
                return false;
            }

            result = (result << 4) | n;
        }

        value = (ushort)result;
        return true;
    }

    /// <summary>Parses 4 hex characters per word into <paramref name="destination"/>; the text must be exactly 4 × words long.</summary>
    public static bool TryParseWords(ReadOnlySpan<byte> text, Span<ushort> destination)
    {
        if (text.Length != destination.Length * 4)
        {
            return false;
        }

        for (int i = 0; i < destination.Length; i++)
        {
            if (!TryParseWord(text.Slice(i * 4, 4), out destination[i]))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Parses a fixed-width field of decimal digits (no sign, no spaces).</summary>
    public static bool TryParseDecimal(ReadOnlySpan<byte> text, out int value)
    {
        value = 0;
        if (text.IsEmpty || text.Length > 9)
        {
            return false;
        }

        foreach (byte c in text)
        {
            if (c < '0' || c > '9')
            {
                value = 0;
                return false;
            }

            value = (value * 10) + (c - '0');
        }

        return true;
    }

    /// <summary>Whether every character of <paramref name="text"/> is a hex digit (either case).</summary>
    public static bool IsHex(ReadOnlySpan<byte> text)
    {
        foreach (byte c in text)
        {
            if (!TryParseNibble(c, out _))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Whether every character of <paramref name="text"/> is a decimal digit.</summary>
    public static bool IsDecimal(ReadOnlySpan<byte> text)
    {
        foreach (byte c in text)
        {
            if (c is < (byte)'0' or > (byte)'9')
            {
                return false;
            }
        }

        return true;
    }
}
