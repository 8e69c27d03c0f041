using System.Globalization;
using System.Text;

namespace OmronHostLink.Worker.Polling;

/// <summary>Parsing, sizes and formatting of a poll group's <see cref="PlcValueType"/>.</summary>
public static class PollValueTypes
{
    /// <summary>The names accepted in configuration, as the console spells them.</summary>
    public static string Names => string.Join(", ", PlcValueTypes.Names);

    /// <summary>Parses a type name (case-insensitive); numbers are refused.</summary>
    public static bool TryParse(string? text, out PlcValueType type) => PlcValueTypes.TryParse(text, out type);

    /// <summary>True when the address is a timer or counter number, read as its completion flag.</summary>
    public static bool IsCompletionFlag(PlcValueType type, PlcAddress address)
        => type == PlcValueType.Bit && address.Area is PlcArea.Timer or PlcArea.Counter;

    /// <summary>How many words <paramref name="count"/> values starting at <paramref name="address"/> occupy.</summary>
    public static int WordCount(PlcValueType type, PlcAddress address, int count) => type switch
    {
        PlcValueType.Int32 or PlcValueType.UInt32 or PlcValueType.Float => checked(2 * count),
        PlcValueType.String => (count + 1) / 2,
        PlcValueType.Bit when IsCompletionFlag(type, address) => 1,
        PlcValueType.Bit => (Math.Max(address.Bit, 0) + count + 15) / 16,
        _ => count,
    };

    /// <summary>Formats the words read as the values, invariant culture: <c>1234</c>, or <c>[1, 2, 3]</c> for several.</summary>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9.</exception>
    public static string Format(PlcValueType type, PlcAddress address, int count, ReadOnlySpan<ushort> words, WordOrder order)
    {
        CultureInfo c = CultureInfo.InvariantCulture;
        if (type == PlcValueType.String)
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
                PlcValueType.Word => "0x" + words[i].ToString("X4", c),
                PlcValueType.Bcd => PlcWords.FromBcd(words[i]).ToString(c),
                PlcValueType.Int16 => PlcWords.ToInt16(words[i]).ToString(c),
                PlcValueType.UInt16 => words[i].ToString(c),
                PlcValueType.Int32 => PlcWords.ReadInt32(words.Slice(2 * i, 2), order).ToString(c),
                PlcValueType.UInt32 => PlcWords.ReadUInt32(words.Slice(2 * i, 2), order).ToString(c),
                PlcValueType.Float => PlcWords.ReadSingle(words.Slice(2 * i, 2), order).ToString("R", c),
                PlcValueType.Bit => PlcWords.GetBit(words[(address.Bit + i) / 16], (address.Bit + i) % 16) ? "1" : "0",
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
