using System.Globalization;
using System.Reflection;
using Microsoft.Extensions.Configuration;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// Checks a configuration section, as written, against the options class it binds to, before the binder sees it. The
/// binder forgives too much: a value it cannot convert inside a dictionary drops the whole link or group without a
/// word, a misspelt key is ignored, a number stands for an enum member that does not exist, and a bare number is a
/// time span of that many days. Here every such value is a failure that names its key.
/// </summary>
/// <remarks>
/// Time spans are durations in the library's one grammar (<see cref="Duration"/>, docs/durations.md): <c>500ms</c>,
/// <c>2s</c>, <c>1.5min</c> or <c>00:00:02</c>; a bare number is refused rather than guessed. <see cref="Bind"/> reads
/// them so; the binder alone would not. Enums take their member names in any case, not numbers. Empty values count as unset.
/// </remarks>
internal static class ConfigurationSchema
{
    /// <summary>The problems of <paramref name="section"/> read as <paramref name="type"/>, each naming its key.</summary>
    /// <param name="section">The section (<c>HostLink</c>, <c>Simulator</c>).</param>
    /// <param name="type">The options class it binds to.</param>
    /// <returns>The failures; empty when the section is well-formed.</returns>
    public static IReadOnlyList<string> Check(IConfigurationSection section, Type type)
    {
        ArgumentNullException.ThrowIfNull(section);
        ArgumentNullException.ThrowIfNull(type);
        var failures = new List<string>();
        if (section.Exists())
        {
            CheckObject(section, section.Path, type, failures, null);
        }

        return failures;
    }

    /// <summary>
    /// Binds <paramref name="section"/> to <paramref name="options"/>, durations read with the library's grammar. Never
    /// throws for a value it cannot convert: <see cref="Check"/> reports that value by its key.
    /// </summary>
    /// <param name="section">The section (<c>HostLink</c>, <c>Simulator</c>).</param>
    /// <param name="options">The options it binds to.</param>
    public static void Bind(IConfigurationSection section, object options)
    {
        ArgumentNullException.ThrowIfNull(section);
        ArgumentNullException.ThrowIfNull(options);
        var values = new Dictionary<string, string?>(StringComparer.OrdinalIgnoreCase);
        if (section.Exists())
        {
            CheckObject(section, section.Path, options.GetType(), [], new Values(section.Path.Length + 1, values));
        }

        try
        {
            new ConfigurationBuilder().AddInMemoryCollection(values).Build().Bind(options);
        }
        catch (InvalidOperationException)
        {
        }
    }

    /// <summary>The values to bind, by their path below the bound section; durations rewritten in the binder's form.</summary>
    private sealed record Values(int PrefixLength, Dictionary<string, string?> ByKey)
    {
        public void Add(string path, string? value, Type type)
            => ByKey[path.Substring(PrefixLength)] = type == typeof(TimeSpan) && Duration.TryParse(value, out TimeSpan t, out _)
                ? t.ToString("c", CultureInfo.InvariantCulture)
                : value;
    }

    /// <summary>True when <paramref name="key"/> is one of <paramref name="type"/>'s own settings.</summary>
    internal static bool IsSetting(Type type, string key) => Settings(type).ContainsKey(key);

    private static void CheckObject(IConfigurationSection section, string path, Type type, List<string> failures, Values? values)
    {
        Dictionary<string, PropertyInfo> settings = Settings(type);
        if (type == typeof(LinkOptions))
        {
            CheckClient(section, path, failures);
        }

        foreach (IConfigurationSection child in section.GetChildren())
        {
            string childPath = $"{path}:{child.Key}";
            if (type == typeof(LinkOptions) && !settings.ContainsKey(child.Key))
            {
                continue;
            }

            if (!settings.TryGetValue(child.Key, out PropertyInfo? property))
            {
                failures.Add($"{childPath} is not a setting here; the settings of {path} are {string.Join(", ", settings.Keys.Order(StringComparer.Ordinal))}.");
                continue;
            }

            CheckValue(child, childPath, property.PropertyType, failures, values);
        }
    }

    /// <summary>
    /// A link's other keys are its client's: read and checked by the library (<see cref="HostLinkClientSettings.Validate"/>),
    /// as the DI package does, for an enabled link.
    /// </summary>
    private static void CheckClient(IConfigurationSection link, string path, List<string> failures)
    {
        if (bool.TryParse(link[nameof(LinkOptions.Enabled)], out bool enabled) && !enabled)
        {
            return;
        }

        var client = new HostLinkClientSettings();
        client.Read(LinkClients.ClientKeys(link));
        failures.AddRange(client.Validate().Select(p => p.Key.Length == 0 ? $"{path}: {p.Message}." : $"{path}:{p.Key}: {p.Message}."));
    }

    private static void CheckValue(IConfigurationSection section, string path, Type type, List<string> failures, Values? values)
    {
        type = Nullable.GetUnderlyingType(type) ?? type;
        bool hasChildren = section.GetChildren().Any();
        if (IsScalar(type))
        {
            if (hasChildren)
            {
                failures.Add($"{path} takes a single value, not a section.");
            }
            else if (!string.IsNullOrEmpty(section.Value))
            {
                CheckScalar(section.Value, path, type, failures);
            }

            values?.Add(path, section.Value, type);
            return;
        }

        if (!hasChildren)
        {
            if (!string.IsNullOrEmpty(section.Value))
            {
                failures.Add($"{path} is a section of settings, not a single value ('{section.Value}').");
            }

            return;
        }

        if (DictionaryValueType(type) is { } valueType)
        {
            foreach (IConfigurationSection child in section.GetChildren())
            {
                CheckValue(child, $"{path}:{child.Key}", valueType, failures, values);
            }
        }
        else if (ElementType(type) is { } elementType)
        {
            foreach (IConfigurationSection child in section.GetChildren())
            {
                if (!int.TryParse(child.Key, NumberStyles.None, CultureInfo.InvariantCulture, out _))
                {
                    failures.Add($"{path}:{child.Key}: {path} is a list; its items are numbered 0, 1, 2…");
                    continue;
                }

                CheckValue(child, $"{path}:{child.Key}", elementType, failures, values);
            }
        }
        else
        {
            CheckObject(section, path, type, failures, values);
        }
    }

    private static void CheckScalar(string value, string path, Type type, List<string> failures)
    {
        if (type == typeof(TimeSpan))
        {
            if (!Duration.TryParse(value, out _, out string? error))
            {
                failures.Add($"{path} {error}.");
            }

            return;
        }

        string? problem = type switch
        {
            _ when type == typeof(string) => null,
            _ when type == typeof(bool) => bool.TryParse(value, out _) ? null : "is not true or false",
            _ when type == typeof(int) => int.TryParse(value, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out _) ? null : "is not a whole number",
            _ when type == typeof(double) => double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out _) ? null : "is not a number",
            _ when type.IsEnum => Enum.GetNames(type).Contains(value.Trim(), StringComparer.OrdinalIgnoreCase)
                ? null
                : $"is not one of {string.Join(", ", Enum.GetNames(type))}",
            _ => null,
        };
        if (problem is not null)
        {
            failures.Add($"{path} '{value}' {problem}.");
        }
    }

    private static bool IsScalar(Type type)
        => type.IsPrimitive || type.IsEnum || type == typeof(string) || type == typeof(TimeSpan) || type == typeof(decimal);

    private static Type? DictionaryValueType(Type type)
        => type.IsGenericType && type.GetGenericTypeDefinition() == typeof(Dictionary<,>) && type.GetGenericArguments()[0] == typeof(string)
            ? type.GetGenericArguments()[1]
            : null;

    private static Type? ElementType(Type type)
        => type.IsArray ? type.GetElementType()
            : type.IsGenericType && type.GetGenericTypeDefinition() is var d && (d == typeof(List<>) || d == typeof(IReadOnlyList<>) || d == typeof(IList<>))
                ? type.GetGenericArguments()[0]
                : null;

    private static Dictionary<string, PropertyInfo> Settings(Type type)
        => type.GetProperties(BindingFlags.Public | BindingFlags.Instance)
            .Where(p => p.SetMethod is { IsPublic: true } && p.GetIndexParameters().Length == 0)
            .ToDictionary(p => p.Name, StringComparer.OrdinalIgnoreCase);
}
