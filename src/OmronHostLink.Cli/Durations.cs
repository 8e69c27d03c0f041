using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;

namespace OmronHostLink.Cli;

/// <summary>
/// Time options, read with the library's one duration grammar (<see cref="Duration"/>, docs/durations.md): the same
/// text means the same time here as in configuration. A bad value is a parse error naming the option, so nothing is sent.
/// </summary>
internal static class Durations
{
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
            Description = $"{description} A duration: {Duration.Forms}.",
            HelpName = "time",
            CustomParser = result => Parse(result, name, min, max),
        };
        if (defaultValue is { } d)
        {
            option.DefaultValueFactory = _ => d;
        }

        return option;
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
            result.AddError($"{name}: give a duration; write {Duration.Forms}.");
            return null;
        }

        string text = result.Tokens[^1].Value;
        if (!Duration.TryParse(text, out TimeSpan value, out string? error))
        {
            result.AddError($"{name}: {error}.");
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
