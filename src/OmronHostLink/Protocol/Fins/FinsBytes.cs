namespace OmronHostLink.Protocol.Fins;

/// <summary>Byte-level helpers shared by the FINS encoders and decoders.</summary>
internal static class FinsBytes
{
    public static ushort ReadUInt16(ReadOnlySpan<byte> source, int offset) => (ushort)((source[offset] << 8) | source[offset + 1]);

    public static void WriteUInt16(Span<byte> destination, int offset, ushort value)
    {
        destination[offset] = (byte)(value >> 8);
        destination[offset + 1] = (byte)value;
    }

    public static uint ReadUInt32(ReadOnlySpan<byte> source, int offset)
        => ((uint)source[offset] << 24) | ((uint)source[offset + 1] << 16) | ((uint)source[offset + 2] << 8) | source[offset + 3];

    public static void WriteUInt32(Span<byte> destination, int offset, uint value)
    {
        destination[offset] = (byte)(value >> 24);
        destination[offset + 1] = (byte)(value >> 16);
        destination[offset + 2] = (byte)(value >> 8);
        destination[offset + 3] = (byte)value;
    }

    /// <summary>Decodes a 2-digit BCD byte; false for a nibble above 9.</summary>
    public static bool TryFromBcd(byte value, out int result)
    {
        int hi = value >> 4;
        int lo = value & 0xF;
        result = (hi * 10) + lo;
        return hi <= 9 && lo <= 9;
    }

    /// <summary>Encodes 0–99 as one BCD byte.</summary>
    public static byte ToBcd(int value) => (byte)(((value / 10) << 4) | (value % 10));

    /// <summary>Writes each byte as two upper-case hex characters.</summary>
    public static void WriteHex(ReadOnlySpan<byte> bytes, Span<byte> destination)
    {
        for (int i = 0; i < bytes.Length; i++)
        {
            HexAscii.WriteByte(bytes[i], destination.Slice(i * 2, 2));
        }
    }

    /// <summary>
    /// Expands <paramref name="count"/> raw bytes held at <c>text[count..2·count]</c> into hex at <c>text[0..2·count]</c>,
    /// in place (each byte is read before the characters that overwrite it are written).
    /// </summary>
    public static void ExpandHexInPlace(Span<byte> text, int count)
    {
        for (int i = 0; i < count; i++)
        {
            byte b = text[count + i];
            HexAscii.WriteByte(b, text.Slice(i * 2, 2));
        }
    }

    /// <summary>Parses hex text into bytes; false for an odd length or a non-hex character.</summary>
    public static bool TryParseHex(ReadOnlySpan<byte> text, Span<byte> destination)
    {
        if ((text.Length & 1) != 0 || destination.Length < text.Length / 2)
        {
            return false;
        }

        for (int i = 0; i < text.Length / 2; i++)
        {
            if (!HexAscii.TryParseByte(text.Slice(i * 2, 2), out destination[i]))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>ASCII text of a fixed-width field, trailing spaces and NULs removed.</summary>
    public static string AsciiTrimmed(ReadOnlySpan<byte> field)
    {
        int end = field.Length;
        while (end > 0 && (field[end - 1] == (byte)' ' || field[end - 1] == 0))
        {
            end--;
        }

        var chars = new char[end];
        for (int i = 0; i < end; i++)
        {
            byte b = field[i];
            chars[i] = b is >= 0x20 and <= 0x7E ? (char)b : '?';
        }

        return new string(chars);
    }

    /// <summary>Writes <paramref name="text"/> into a fixed-width ASCII field padded with spaces.</summary>
    public static void WriteAsciiPadded(string text, Span<byte> field)
    {
        if (text.Length > field.Length)
        {
            throw new ArgumentException($"'{text}' is longer than its {field.Length}-character field.", nameof(text));
        }

        for (int i = 0; i < field.Length; i++)
        {
            if (i < text.Length)
            {
                char c = text[i];
                if (c is < ' ' or > '~')
                {
                    throw new ArgumentException($"The character at position {i} of '{text}' is not printable ASCII.", nameof(text));
                }

                field[i] = (byte)c;
            }
            else
            {
                field[i] = (byte)' ';
            }
        }
    }
}
