using System.Globalization;

namespace OmronHostLink;

/// <summary>One key's value, converted on request; a value that cannot be converted is recorded as a problem at its key.</summary>
internal sealed class SettingValue
{
    private readonly SettingNode _node;
    private readonly string _key;
    private readonly List<HostLinkSettingsProblem> _problems;

    public SettingValue(SettingNode node, string key, List<HostLinkSettingsProblem> problems)
    {
        _node = node;
        _key = key;
        _problems = problems;
    }

    public bool IsSection => _node.Children.Count > 0;

    /// <summary>The value as written, unchecked; a section may carry one too.</summary>
    public string? WrittenValue => _node.Value;

    public void Problem(string message) => _problems.Add(new HostLinkSettingsProblem(_key, message));

    /// <summary>The text; null when the key is null in the file (left at the default) or cannot be used.</summary>
    public string? Text()
    {
        if (IsSection)
        {
            Problem("expects a value, not a section");
            return null;
        }

        string? text = _node.Value;
        if (text is not null && text.Trim().Length == 0)
        {
            Problem("is empty; write a value, or remove the key to use the default");
            return null;
        }

        return text;
    }

    public int? Integer()
    {
        string? text = Text();
        if (text is null)
        {
            return null;
        }

        if (int.TryParse(text.Trim(), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int value))
        {
            return value;
        }

        Problem($"'{text}' is not a whole number");
        return null;
    }

    public bool? Boolean()
    {
        string? text = Text();
        if (text is null)
        {
            return null;
        }

        if (bool.TryParse(text.Trim(), out bool value))
        {
            return value;
        }

        Problem($"'{text}' is not true or false");
        return null;
    }

    /// <summary>A duration in the library's one grammar (<see cref="OmronHostLink.Duration"/>).</summary>
    public TimeSpan? Duration()
    {
        string? text = Text();
        if (text is null)
        {
            return null;
        }

        if (OmronHostLink.Duration.TryParse(text, out TimeSpan value, out string? error))
        {
            return value;
        }

        Problem(error!);
        return null;
    }

    /// <summary>An enum member by name (any case); numbers only where <paramref name="aliases"/> allow them.</summary>
    public TEnum? Choice<TEnum>(params (string Text, TEnum Value)[] aliases)
        where TEnum : struct, Enum
    {
        string? text = Text();
        if (text is null)
        {
            return null;
        }

        string t = text.Trim();
        foreach (string name in Enum.GetNames(typeof(TEnum)))
        {
            if (name.Equals(t, StringComparison.OrdinalIgnoreCase))
            {
                return (TEnum)Enum.Parse(typeof(TEnum), name);
            }
        }

        foreach ((string alias, TEnum value) in aliases)
        {
            if (alias.Equals(t, StringComparison.OrdinalIgnoreCase))
            {
                return value;
            }
        }

        IEnumerable<string> accepted = Enum.GetNames(typeof(TEnum)).Concat(aliases.Select(a => a.Text));
        Problem($"'{text}' is not one of {string.Join(", ", accepted)}");
        return null;
    }

    /// <summary>
    /// A section of unit numbers to durations (<c>"UnitSendIntervals": { "3": "200ms" }</c>); null when the key is null
    /// in the file or nothing in it can be used. A key that is not a unit number is a problem at its own key path.
    /// </summary>
    public IDictionary<int, TimeSpan>? UnitDurations()
    {
        if (!IsSection)
        {
            if (_node.Value is not null)
            {
                Problem("expects a section of unit numbers and durations, such as \"3\": \"200ms\"");
            }

            return null;
        }

        var map = new Dictionary<int, TimeSpan>();
        foreach (SettingNode child in _node.Children)
        {
            var value = new SettingValue(child, _key + ":" + child.Key, _problems);
            if (!int.TryParse(child.Key.Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out int unit))
            {
                value.Problem($"'{child.Key}' is not a unit number (0-{HostLinkRules.MaxUnitNumber})");
            }
            else if (value.Duration() is { } duration)
            {
                map[unit] = duration;
            }
        }

        return map.Count == 0 ? null : map;
    }

    public void Section<T>(SettingKeys<T> keys, T target)
    {
        if (!IsSection && _node.Value is not null)
        {
            Problem($"expects a section ({string.Join(", ", keys)}), not a value");
            return;
        }

        keys.Read(_node, _key + ":", target, _problems);
    }
}
