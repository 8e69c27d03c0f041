using System.Text.Json;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Configuration.Json;
using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// The checks that no section's validator can make, run before the host is built: a configuration file that cannot be
/// read (a JSON syntax error, a key given twice, also in another case), a misspelt or unknown section, a log level
/// that does not exist (the host could not even be built). Each problem names its file and line, or its key. Every
/// key within a section is the section's validator's (<see cref="SectionValidator{TOptions}"/>).
/// </summary>
internal static class ConfigurationPreflight
{

    /// <summary>Keys the generic host reads at the top level of the configuration files.</summary>
    private static readonly string[] HostKeys = ["AllowedHosts", "urls", "environment", "applicationName", "contentRoot", "Kestrel"];

    /// <summary>What is wrong with a configuration that could not be loaded, in one line; null if the exception is no such problem.</summary>
    public static string? LoadProblem(Exception e)
    {
        ArgumentNullException.ThrowIfNull(e);
        if (e is not InvalidDataException { InnerException: { } inner } || !e.Message.StartsWith("Failed to load configuration", StringComparison.Ordinal))
        {
            return null;
        }

        string? path = e.Message.Split('\'') is { Length: >= 3 } parts ? parts[1] : null;
        string file = path is null ? "a configuration file" : Path.GetFileName(path);
        for (Exception? x = inner; x is not null; x = x.InnerException)
        {
            if (x is JsonException)
            {
                inner = x;
                break;
            }
        }

        return inner switch
        {
            JsonException { LineNumber: { } line, BytePositionInLine: { } column } json
                => $"{file}, line {line + 1}, column {column + 1}: {StripPosition(json.Message)}",
            FormatException duplicate when duplicate.Message.Contains("duplicate key", StringComparison.OrdinalIgnoreCase)
                => Duplicate(path, file, duplicate.Message),
            _ => $"{file}: {inner.Message}",
        };
    }

    /// <summary>A key given twice: the key, and its lines when the file tells them.</summary>
    private static string Duplicate(string? path, string file, string message)
    {
        // "A duplicate key 'HostLink:Links:plc:Groups:levels:Address' was found."
        string[] quoted = message.Split('\'');
        string? key = quoted.Length >= 3 ? quoted[1] : null;
        if (key is null)
        {
            return $"{file}: {message.TrimEnd('.')} (keys are compared ignoring case: write each key once).";
        }

        return path is not null && DuplicateKeys.Lines(path, key) is var (first, second)
            ? $"{file}, line {second}: duplicate key '{key}', given on line {first} already (keys are compared ignoring case: write each key once)."
            : $"{file}: duplicate key '{key}' (keys are compared ignoring case: write each key once).";
    }

    /// <summary>Problems of the configuration as a whole, each naming its key.</summary>
    /// <param name="configuration">The whole configuration.</param>
    /// <param name="sections">The sections the gateway reads, besides the generic host's own.</param>
    public static List<string> Check(IConfiguration configuration, IReadOnlyList<string> sections)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        ArgumentNullException.ThrowIfNull(sections);
        var failures = new List<string>();
        CheckSections(configuration, sections, failures);
        CheckLogLevels(configuration, failures);
        return failures;
    }

    private static void CheckSections(IConfiguration configuration, IReadOnlyList<string> sections, List<string> failures)
    {
        // A file's top level is the gateway's to define; environment variables and the command line also carry the
        // machine's own (PATH, HOME), so there only a near miss of a section's name is taken for a typo.
        var fromFiles = new HashSet<string>(StringComparer.OrdinalIgnoreCase);
        if (configuration is IConfigurationRoot root)
        {
            foreach (FileConfigurationProvider file in root.Providers.OfType<FileConfigurationProvider>())
            {
                foreach (string key in file.GetChildKeys([], null))
                {
                    fromFiles.Add(key);
                }
            }
        }

        foreach (IConfigurationSection section in configuration.GetChildren())
        {
            if (sections.Contains(section.Key, StringComparer.OrdinalIgnoreCase) || HostKeys.Contains(section.Key, StringComparer.OrdinalIgnoreCase))
            {
                continue;
            }

            string? near = sections.FirstOrDefault(s => Distance(s.ToUpperInvariant(), section.Key.ToUpperInvariant()) <= 2);
            if (near is not null && (section.GetChildren().Any() || fromFiles.Contains(section.Key)))
            {
                failures.Add($"{section.Key} is not a section the gateway reads; did you mean {near}? The sections are {string.Join(", ", sections)}.");
            }
            else if (near is null && fromFiles.Contains(section.Key))
            {
                failures.Add($"{section.Key} is not a section the gateway reads; the sections are {string.Join(", ", sections)}.");
            }
        }
    }

    /// <summary>
    /// The keys of log levels that do not exist. The logging framework would throw on them while the host is built;
    /// the caller reports them and overrides them with a valid level, so the other sections can still be checked.
    /// </summary>
    public static List<string> BadLogLevels(IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        IConfigurationSection logging = configuration.GetSection("Logging");

        // Logging:LogLevel:<category> and Logging:<provider>:LogLevel:<category>.
        return logging.GetSection("LogLevel").GetChildren()
            .Concat(logging.GetChildren().SelectMany(p => p.GetSection("LogLevel").GetChildren()))
            .Where(l => l.Value is { Length: > 0 } value && (!Enum.TryParse<LogLevel>(value, ignoreCase: true, out _) || int.TryParse(value, out _)))
            .Select(l => l.Path)
            .Distinct(StringComparer.OrdinalIgnoreCase)
            .ToList();
    }

    private static void CheckLogLevels(IConfiguration configuration, List<string> failures)
    {
        foreach (string key in BadLogLevels(configuration))
        {
            failures.Add($"{key} '{configuration[key]}' is not a log level: {string.Join(", ", Enum.GetNames<LogLevel>())}.");
        }
    }

    private static string StripPosition(string message)
    {
        int at = message.IndexOf(" LineNumber:", StringComparison.Ordinal);
        return (at < 0 ? message : message.Substring(0, at)).TrimEnd();
    }

    /// <summary>Levenshtein distance, for telling a typo of a section name (Mqt, HostLinks) from another key.</summary>
    private static int Distance(string a, string b)
    {
        var previous = new int[b.Length + 1];
        var current = new int[b.Length + 1];
        for (int j = 0; j <= b.Length; j++)
        {
            previous[j] = j;
        }

        for (int i = 1; i <= a.Length; i++)
        {
            current[0] = i;
            for (int j = 1; j <= b.Length; j++)
            {
                current[j] = Math.Min(Math.Min(current[j - 1] + 1, previous[j] + 1), previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1));
            }

            (previous, current) = (current, previous);
        }

        return previous[b.Length];
    }
}
