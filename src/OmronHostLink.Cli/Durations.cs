using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;

namespace OmronHostLink.Cli;

/// <summary>
/// The one rule for every time option: <c>500ms</c>, <c>1s</c>, <c>1.5s</c>, <c>2m</c>, <c>1h</c>; a bare number is
/// milliseconds. A bad value is a parse error naming the option, so nothing is sent.
/// </summary>
internal static class Durations
{
    /// <summary>The hint every duration error ends with.</summary>
    public const string Hint = "use 500ms, 1s or 2m";

    /// <summary>A time option parsed with the duration rule.</summary>
    /// <param name="name">The option, e.g. <c>--timeout</c>.</param>
    /// <param name="description">Help text; the rule is appended.</param>
    /// <param name="defaultValue">The value when the option is not given (help shows it); null for none.</param>
    /// <param name="min">The shortest accepted value (zero where "no wait" makes sense).</param>
    /// <param name="max">The longest accepted value.</param>
    public static Option<TimeSpan?> Option(string name, string description, TimeSpan? defaultValue, TimeSpan min, TimeSpan max)
    {
        var option = new Option<TimeSpan?>(name)
        {
            Description = description + " A duration: 500ms, 1s, 2m (a bare number is milliseconds).",
            HelpName = "time",
            CustomParser = result => Parse(result, name, min, max),
        };
        if (defaultValue is { } d)
        {
            option.DefaultValueFactory = _ => d;
        }

        return option;
    }

    /// <summary>Parses <paramref name="text"/> with the duration rule.</summary>
    /// <returns>False when the text is not a duration.</returns>
    public static bool TryParse(string text, out TimeSpan value)
    {
        value = default;
        string t = text.Trim().ToLowerInvariant();
        double factor = 1;
        if (t.EndsWith("ms", StringComparison.Ordinal))
        {
            t = t[..^2];
        }
        else if (t.EndsWith('s'))
        {
            factor = 1000;
            t = t[..^1];
        }
        else if (t.EndsWith('m'))
        {
            factor = 60_000;
            t = t[..^1];
        }
        else if (t.EndsWith('h'))
        {
            factor = 3_600_000;
            t = t[..^1];
        }

        if (t.Length == 0
            || !double.TryParse(t, NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out double n)
            || !double.IsFinite(n)
            || n * factor > TimeSpan.MaxValue.TotalMilliseconds / 2)
        {
            return false;
        }

        value = TimeSpan.FromMilliseconds(n * factor);
        return true;
    }

    /// <summary>A duration the way a user writes one: <c>250 ms</c>, <c>1.5 s</c>, <c>2 min</c>.</summary>
    public static string Format(TimeSpan value)
        => value.TotalMilliseconds < 1000 ? $"{value.TotalMilliseconds.ToString("0.###", CultureInfo.InvariantCulture)} ms"
            : value.TotalSeconds < 120 ? $"{value.TotalSeconds.ToString("0.###", CultureInfo.InvariantCulture)} s"
            : $"{value.TotalMinutes.ToString("0.###", CultureInfo.InvariantCulture)} min";

    private static TimeSpan? Parse(ArgumentResult result, string name, TimeSpan min, TimeSpan max)
    {
        if (result.Tokens.Count == 0)
        {
            result.AddError($"{name}: give a duration; {Hint}.");
            return null;
        }

        string text = result.Tokens[^1].Value;
        if (!TryParse(text, out TimeSpan value))
        {
            result.AddError($"{name}: '{text}' is not a duration; {Hint}.");
            return null;
        }

        if (value < min || value > max)
        {
            result.AddError($"{name}: '{text}' is out of range; it must be {Format(min)} to {Format(max)}.");
            return null;
        }

        return value;
    }
}
