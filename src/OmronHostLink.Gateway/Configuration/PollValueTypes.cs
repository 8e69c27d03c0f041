using System.Globalization;
using System.Text;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>Parsing, sizes and formatting of a poll group's <see cref="PlcValueType"/>.</summary>
internal static class PollValueTypes
{
    /// <summary>The names accepted in configuration, as the console spells them.</summary>
    public static string Names => string.Join(", ", PlcValueTypes.Names);

    /// <summary>Parses a type name (case-insensitive); numbers are refused.</summary>
    public static bool TryParse(string? text, out PlcValueType type) => PlcValueTypes.TryParse(text, out type);

    /// <summary>True when the address is a timer or counter number, read as its completion flag.</summary>
    public static bool IsCompletionFlag(PlcValueType type, PlcAddress address)
        => type == PlcValueType.Bit && address.Area is PlcArea.Timer or PlcArea.Counter;

    /// <summary>How many words <paramref name="count"/> values starting at <paramref name="address"/> occupy.</summary>
    public static int WordCount(PlcValueType type, PlcAddress address, int count)
        => IsCompletionFlag(type, address) ? 1 : PlcValueCodec.WordCount(type, count, Math.Max(address.Bit, 0));

    /// <summary>Formats the words read as the values, invariant culture: <c>1234</c>, or <c>[1, 2, 3]</c> for several.</summary>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9, or text a byte above 0x7F.</exception>
    public static string Format(PlcValueType type, PlcAddress address, int count, ReadOnlySpan<ushort> words, WordOrder order)
    {
        PlcValue[] values = PlcValueCodec.DecodeValues(type, words, count, order, Math.Max(address.Bit, 0));
        if (type == PlcValueType.String)
        {
            return Quote(values[0].ToString());
        }

        return values.Length == 1 ? values[0].ToString() : "[" + string.Join(", ", values) + "]";
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
