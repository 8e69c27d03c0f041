using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// The one way a duration is written, in configuration and on the command line alike: a number and a unit
/// (<c>500ms</c>, <c>2s</c>, <c>1.5min</c>, <c>2m</c>, <c>1h</c>; a space between them is allowed), or the
/// <see cref="TimeSpan"/> form <c>[d.]hh:mm:ss[.fffffff]</c> (<c>00:00:02</c>). Units: <c>ms</c>, <c>s</c>,
/// <c>m</c> or <c>min</c>, <c>h</c>, in any case.
/// </summary>
/// <remarks>
/// A bare number is refused, with a hint showing the units: <c>300</c> is 300 ms to one reader and 300 s to another
/// (configuration binders read it as days). <c>0</c> alone is zero, which every unit agrees on. Negative durations
/// are refused.
/// </remarks>
public static class Duration
{
    /// <summary>How a duration may be written, for messages.</summary>
    public const string Forms = "300ms, 1.5s, 2m or 00:00:00.300";

    /// <summary>Reads a duration.</summary>
    /// <param name="text">The text as written.</param>
    /// <param name="value">The duration when the text is one.</param>
    /// <param name="error">Why the text is not a duration, in the writer's words (<c>'300' has no unit; …</c>); null when it is one.</param>
    /// <returns>True when the text is a duration.</returns>
    public static bool TryParse(string? text, out TimeSpan value, out string? error)
    {
        value = default;
        error = null;
        string t = (text ?? "").Trim();
        if (t.IndexOf(':') >= 0)
        {
            if (t[0] != '-' && TimeSpan.TryParse(t, CultureInfo.InvariantCulture, out value))
            {
                return true;
            }

            value = default;
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
        decimal amount = 0;
        bool isNumber = number.Length > 0
            && decimal.TryParse(number, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out amount);
        if (isNumber && unit.Length == 0)
        {
            if (amount == 0)
            {
                return true;
            }

            // The time-span example shows the reader's own number, taken as milliseconds.
            string asTimeSpan = amount < 86_400_000m
                ? TimeSpan.FromTicks((long)(amount * TimeSpan.TicksPerMillisecond)).ToString(@"hh\:mm\:ss\.FFFFFFF", CultureInfo.InvariantCulture).TrimEnd('.')
                : "hh:mm:ss";
            error = $"'{text}' has no unit; write {number}ms, {number}s or {number}m (or {asTimeSpan} for {number}ms)";
            return false;
        }

        decimal ticksPerUnit = unit switch
        {
            "ms" => TimeSpan.TicksPerMillisecond,
            "s" => TimeSpan.TicksPerSecond,
            "m" or "min" => TimeSpan.TicksPerMinute,
            "h" => TimeSpan.TicksPerHour,
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

    /// <summary>Reads a duration, or throws saying why the text is not one.</summary>
    /// <param name="text">The text as written.</param>
    /// <returns>The duration.</returns>
    /// <exception cref="FormatException">The text is not a duration; the message says how to write one.</exception>
    public static TimeSpan Parse(string text)
        => TryParse(text, out TimeSpan value, out string? error) ? value : throw new FormatException(error);
}
