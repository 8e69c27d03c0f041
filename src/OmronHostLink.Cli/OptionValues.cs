using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli;

/// <summary>
/// Options and arguments whose values are parsed the user's way: numbers in decimal or 0x-hex, choices in any case,
/// and a bad value reported as a parse error that names the option and what it takes ("--unit: 'x' is not a whole
/// number 0-31."), never a .NET type name. Nothing is sent when one fails.
/// </summary>
internal static class OptionValues
{
    /// <summary>A whole-number option with a default.</summary>
    public static Option<int> Integer(string name, string description, int defaultValue, int min, int max, string helpName)
        => new(name)
        {
            Description = description,
            HelpName = helpName,
            DefaultValueFactory = _ => defaultValue,
            CustomParser = result => ParseInteger(result, name, min, max) ?? defaultValue,
        };

    /// <summary>A whole-number option that may be left out (null).</summary>
    public static Option<int?> OptionalInteger(string name, string description, int min, int max, string helpName)
        => new(name)
        {
            Description = description,
            HelpName = helpName,
            CustomParser = result => ParseInteger(result, name, min, max),
        };

    /// <summary>An option that takes one of a few words, in any case; the value is the word in lower case.</summary>
    public static Option<string> Choice(string name, string description, string defaultValue, params string[] choices)
        => new(name)
        {
            Description = description,
            HelpName = string.Join('|', choices),
            DefaultValueFactory = _ => defaultValue,
            CustomParser = result => ParseChoice(result, name, choices) ?? defaultValue,
        };

    /// <summary>An option that takes one of a few words, in any case, or is left out (null).</summary>
    public static Option<string?> OptionalChoice(string name, string description, string helpName, params string[] choices)
        => new(name)
        {
            Description = description,
            HelpName = helpName,
            CustomParser = result => ParseChoice(result, name, choices),
        };

    /// <summary>An argument that takes one of a few words, in any case; the value is the word in lower case.</summary>
    public static Argument<string> ChoiceArgument(string name, string description, params string[] choices)
    {
        var argument = new Argument<string>(name)
        {
            Description = description,
            HelpName = string.Join('|', choices),
            CustomParser = result => ParseChoice(result, name, choices) ?? choices[0],
        };
        return argument;
    }

    /// <summary>A probability 0-1 (<c>--fault-drop 0.02</c>).</summary>
    public static Option<double> Probability(string name, string description)
        => new(name)
        {
            Description = description + " 0-1.",
            HelpName = "p",
            DefaultValueFactory = _ => 0,
            CustomParser = result =>
            {
                string text = Token(result);
                if (double.TryParse(text, NumberStyles.AllowDecimalPoint | NumberStyles.AllowExponent, CultureInfo.InvariantCulture, out double p) && p is >= 0 and <= 1)
                {
                    return p;
                }

                result.AddError($"{name}: '{text}' is not a probability 0-1 (for example 0.02).");
                return 0;
            },
        };

    /// <summary>A serial-settings error in the console's terms: the option instead of the property.</summary>
    public static string SerialMessage(ArgumentException e)
    {
        string message = Addresses.FirstSentence(e.Message);
        string? option = e.ParamName switch
        {
            nameof(SerialLineSettings.BaudRate) => "--baud",
            nameof(SerialLineSettings.DataBits) => "--data-bits",
            nameof(SerialLineSettings.Parity) => "--parity",
            nameof(SerialLineSettings.StopBits) => "--stop-bits",
            nameof(SerialLineSettings.PortName) => "--port",
            _ => null,
        };
        return option is null
            ? "The serial settings are not valid: " + message
            : option + ": " + message.Replace($"{nameof(SerialLineSettings)}.{e.ParamName} ", string.Empty, StringComparison.Ordinal);
    }

    private static int? ParseInteger(ArgumentResult result, string name, int min, int max)
    {
        string text = Token(result);
        if (Numbers.TryParseInteger(text, min, max, out long value))
        {
            return (int)value;
        }

        string range = min == int.MinValue && max == int.MaxValue ? "" : max == int.MaxValue ? $" of at least {min}" : $" {min}-{max}";
        result.AddError(Numbers.TryParseInteger(text, long.MinValue, long.MaxValue, out _)
            ? $"{name}: {text} is not{range}."
            : $"{name}: '{text}' is not a whole number{range}.");
        return null;
    }

    private static string? ParseChoice(ArgumentResult result, string name, string[] choices)
    {
        string text = Token(result);
        string lower = text.Trim().ToLowerInvariant();
        if (choices.Contains(lower, StringComparer.Ordinal))
        {
            return lower;
        }

        result.AddError($"{name}: '{text}' is not one of {string.Join(", ", choices)}.");
        return null;
    }

    private static string Token(ArgumentResult result) => result.Tokens.Count == 0 ? string.Empty : result.Tokens[^1].Value;
}
