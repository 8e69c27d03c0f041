using System.Globalization;

namespace OmronHostLink.Cli;

/// <summary>Parsing of the numbers a user types: decimal, or hex with 0x.</summary>
internal static class Numbers
{
    /// <summary>Parses a whole number in decimal or 0x-hex within [min, max].</summary>
    public static bool TryParseInteger(string text, long min, long max, out long value)
    {
        text = text.Trim().Replace("_", string.Empty, StringComparison.Ordinal);
        bool ok;
        if (text.StartsWith("0x", StringComparison.OrdinalIgnoreCase))
        {
            ok = ulong.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ulong hex) && hex <= long.MaxValue;
            value = ok ? (long)hex : 0;
        }
        else
        {
            ok = long.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out value);
        }

        return ok && value >= min && value <= max;
    }

    /// <summary>Parses a whole number or throws a usage error naming <paramref name="what"/>.</summary>
    public static long ParseInteger(string text, long min, long max, string what)
        => TryParseInteger(text, min, max, out long value)
            ? value
            : throw new UsageException($"{what} '{text}' is not a number {Range(min, max)} (decimal, or hex with 0x).");

    /// <summary>Parses a unit list: <c>0-31</c>, <c>0,1,5</c>, <c>0-3,7</c>.</summary>
    public static IReadOnlyList<int> ParseUnits(string text, string option)
    {
        var units = new SortedSet<int>();
        foreach (string part in text.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            int dash = part.IndexOf('-', 1);
            if (dash > 0)
            {
                int from = (int)ParseInteger(part[..dash], 0, SettingRules.MaxUnitNumber, option + " unit");
                int to = (int)ParseInteger(part[(dash + 1)..], 0, SettingRules.MaxUnitNumber, option + " unit");
                if (to < from)
                {
                    throw new UsageException($"{option}: the range {part} runs backwards.");
                }

                for (int u = from; u <= to; u++)
                {
                    units.Add(u);
                }
            }
            else
            {
                units.Add((int)ParseInteger(part, 0, SettingRules.MaxUnitNumber, option + " unit"));
            }
        }

        if (units.Count == 0)
        {
            throw new UsageException($"{option} names no unit; write for example 0-{SettingRules.MaxUnitNumber} or 0,1,5.");
        }

        return units.ToArray();
    }

    public static string Hex(ushort word) => "0x" + word.ToString("X4", CultureInfo.InvariantCulture);

    public static string Hex(uint value) => "0x" + value.ToString("X8", CultureInfo.InvariantCulture);

    public static string Invariant(IFormattable value) => value.ToString(null, CultureInfo.InvariantCulture);

    private static string Range(long min, long max)
        => min == long.MinValue ? string.Empty : $"{min.ToString(CultureInfo.InvariantCulture)}-{max.ToString(CultureInfo.InvariantCulture)}";
}
