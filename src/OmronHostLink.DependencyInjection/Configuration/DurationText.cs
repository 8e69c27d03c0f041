using System.Globalization;

namespace OmronHostLink.DependencyInjection.Configuration;

/// <summary>
/// Durations as configuration writes them: <c>300ms</c>, <c>1.5s</c>, <c>2m</c>, or the <see cref="TimeSpan"/> form
/// <c>00:00:00.300</c>. A bare number is refused: whether <c>300</c> meant milliseconds or seconds cannot be told.
/// </summary>
internal static class DurationText
{
    /// <summary>How a duration may be written, for messages.</summary>
    public const string Forms = "300ms, 1.5s, 2m or 00:00:00.300";

    /// <summary>Reads a duration.</summary>
    /// <param name="text">The configuration value.</param>
    /// <param name="value">The duration when the text is one.</param>
    /// <param name="error">Why the text is not a duration, else null.</param>
    /// <returns>True when the text is a duration.</returns>
    public static bool TryParse(string text, out TimeSpan value, out string? error)
    {
        value = default;
        error = null;
        string t = text.Trim();
        if (t.IndexOf(':') >= 0)
        {
            if (TimeSpan.TryParse(t, CultureInfo.InvariantCulture, out value))
            {
                return true;
            }

            error = $"'{text}' is not a duration; write {Forms}";
            return false;
        }

        int unitStart = t.Length;
        while (unitStart > 0 && char.IsLetter(t[unitStart - 1]))
        {
            unitStart--;
        }

        string number = t.Substring(0, unitStart).TrimEnd();
        string unit = t.Substring(unitStart).ToLowerInvariant();
        bool isNumber = decimal.TryParse(number, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out decimal amount);
        if (isNumber && unit.Length == 0)
        {
            error = $"'{text}' has no unit; write {number}ms, {number}s or {number}m (or 00:00:00.300)";
            return false;
        }

        decimal ticksPerUnit = unit switch
        {
            "ms" => TimeSpan.TicksPerMillisecond,
            "s" => TimeSpan.TicksPerSecond,
            "m" => TimeSpan.TicksPerMinute,
            _ => 0,
        };
        if (!isNumber || ticksPerUnit == 0)
        {
            error = $"'{text}' is not a duration; write {Forms}";
            return false;
        }

        if (amount > TimeSpan.MaxValue.Ticks / ticksPerUnit)
        {
            error = $"'{text}' is too long a duration";
            return false;
        }

        value = TimeSpan.FromTicks((long)decimal.Round(amount * ticksPerUnit, MidpointRounding.AwayFromZero));
        return true;
    }
}
