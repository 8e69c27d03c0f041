using System.Globalization;
using System.Text;

namespace OmronHostLink.Worker.Polling;

/// <summary>How a poll group's words are read as values (the console's <c>--as</c>).</summary>
public enum PollValueType
{
    /// <summary>Raw words, shown in hex.</summary>
    Word,

    /// <summary>4-digit BCD words (0-9999).</summary>
    Bcd,

    /// <summary>Signed 16-bit.</summary>
    Int16,

    /// <summary>Unsigned 16-bit.</summary>
    UInt16,

    /// <summary>Signed 32-bit, two words.</summary>
    Int32,

    /// <summary>Unsigned 32-bit, two words.</summary>
    UInt32,

    /// <summary>IEEE 754 single (REAL), two words.</summary>
    Float,

    /// <summary>ASCII text, two characters a word; the count is in characters.</summary>
    String,

    /// <summary>Bits from a bit address on (or one timer/counter completion flag); the count is in bits.</summary>
    Bit,
}

/// <summary>Parsing, sizes and formatting of <see cref="PollValueType"/>.</summary>
public static class PollValueTypes
{
    /// <summary>The names accepted in configuration, as the console spells them.</summary>
    public const string Names = "word, bcd, int16, uint16, int32, uint32, float, string, bit";

    /// <summary>Parses a type name (case-insensitive); numbers are refused.</summary>
    public static bool TryParse(string? text, out PollValueType type)
    {
        type = default;
        string? t = text?.Trim().ToLowerInvariant();
        switch (t)
        {
            case "word": type = PollValueType.Word; return true;
            case "bcd": type = PollValueType.Bcd; return true;
            case "int16": type = PollValueType.Int16; return true;
            case "uint16": type = PollValueType.UInt16; return true;
            case "int32": type = PollValueType.Int32; return true;
            case "uint32": type = PollValueType.UInt32; return true;
            case "float": type = PollValueType.Float; return true;
            case "string": type = PollValueType.String; return true;
            case "bit": type = PollValueType.Bit; return true;
            default: return false;
        }
    }

    /// <summary>True when the address is a timer or counter number, read as its completion flag.</summary>
    public static bool IsCompletionFlag(PollValueType type, PlcAddress address)
        => type == PollValueType.Bit && address.Area is PlcArea.Timer or PlcArea.Counter;

    /// <summary>How many words <paramref name="count"/> values starting at <paramref name="address"/> occupy.</summary>
    public static int WordCount(PollValueType type, PlcAddress address, int count) => type switch
    {
        PollValueType.Int32 or PollValueType.UInt32 or PollValueType.Float => checked(2 * count),
        PollValueType.String => (count + 1) / 2,
        PollValueType.Bit when IsCompletionFlag(type, address) => 1,
        PollValueType.Bit => (Math.Max(address.Bit, 0) + count + 15) / 16,
        _ => count,
    };

    /// <summary>Formats the words read as the values, invariant culture: <c>1234</c>, or <c>[1, 2, 3]</c> for several.</summary>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9.</exception>
    public static string Format(PollValueType type, PlcAddress address, int count, ReadOnlySpan<ushort> words, WordOrder order)
    {
        CultureInfo c = CultureInfo.InvariantCulture;
        if (type == PollValueType.String)
        {
            string text = PlcWords.ReadString(words);
            if (text.Length > count)
            {
                text = text.Substring(0, count);
            }

            return Quote(text);
        }

        var values = new string[count];
        for (int i = 0; i < count; i++)
        {
            values[i] = type switch
            {
                PollValueType.Word => "0x" + words[i].ToString("X4", c),
                PollValueType.Bcd => PlcWords.FromBcd(words[i]).ToString(c),
                PollValueType.Int16 => PlcWords.ToInt16(words[i]).ToString(c),
                PollValueType.UInt16 => words[i].ToString(c),
                PollValueType.Int32 => PlcWords.ReadInt32(words.Slice(2 * i, 2), order).ToString(c),
                PollValueType.UInt32 => PlcWords.ReadUInt32(words.Slice(2 * i, 2), order).ToString(c),
                PollValueType.Float => PlcWords.ReadSingle(words.Slice(2 * i, 2), order).ToString("R", c),
                PollValueType.Bit => PlcWords.GetBit(words[(address.Bit + i) / 16], (address.Bit + i) % 16) ? "1" : "0",
                _ => throw new ArgumentOutOfRangeException(nameof(type), type, null),
            };
        }

        return count == 1 ? values[0] : "[" + string.Join(", ", values) + "]";
    }

    private static string Quote(string text)
    {
        var sb = new StringBuilder(text.Length + 2).Append('"');
        foreach (char ch in text)
        {
            if (ch is '"' or '\\')
            {
                sb.Append('\\').Append(ch);
            }
            else if (ch < ' ' || ch > '~')
            {
                sb.Append("\\x").Append(((int)ch).ToString("X2", CultureInfo.InvariantCulture));
            }
            else
            {
                sb.Append(ch);
            }
        }

        return sb.Append('"').ToString();
    }
}
