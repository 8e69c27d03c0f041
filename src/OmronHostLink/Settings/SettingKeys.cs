namespace OmronHostLink;

/// <summary>
/// The keys one settings section may hold and how each is read. Keys match without regard to case, as configuration
/// does; an unknown key is a problem that suggests the key meant.
/// </summary>
internal sealed class SettingKeys<T> : IEnumerable<string>
{
    private readonly Dictionary<string, Action<SettingValue, T>> _readers = new(StringComparer.OrdinalIgnoreCase);
    private readonly List<string> _names = new();
    private readonly string _what;

    private readonly Dictionary<string, string> _renamed = new(StringComparer.OrdinalIgnoreCase);

    public SettingKeys(string what) => _what = what;

    /// <summary>The keys of declared settings (with the keys they had before a rename) and of sections read by hand.</summary>
    public static SettingKeys<T> Of<TOptions>(string what, IEnumerable<Setting<T, TOptions>> declared, params (string Name, Action<SettingValue, T> Read)[] sections)
        where TOptions : new()
    {
        var keys = new SettingKeys<T>(what);
        foreach ((string name, Action<SettingValue, T> read) in sections)
        {
            keys.Add(name, read);
        }

        foreach (Setting<T, TOptions> setting in declared)
        {
            keys.Add(setting.Key, setting.Read);
            if (setting.FormerKey is { } former)
            {
                keys._renamed.Add(former, setting.Key);
            }
        }

        return keys;
    }

    /// <summary>A key that was renamed or moved (<c>LineBaudRate</c> → <c>Serial:BaudRate</c>): reading it says where it is now.</summary>
    public SettingKeys<T> WithRenamed(string former, string now)
    {
        _renamed.Add(former, now);
        return this;
    }

    public void Add(string name, Action<SettingValue, T> read)
    {
        _readers.Add(name, read);
        _names.Add(name);
    }

    /// <summary>
    /// Reads every child of <paramref name="section"/> into <paramref name="target"/>, recording in
    /// <paramref name="problems"/> (at keys starting with <paramref name="prefix"/>) what cannot be used; <paramref name="suggest"/>
    /// names other places a key may belong (<c>BaudRate</c> → <c>Serial:BaudRate</c>), or is null.
    /// </summary>
    public void Read(SettingNode section, string prefix, T target, List<HostLinkSettingsProblem> problems, Func<string, string?>? suggest = null)
    {
        foreach (SettingNode child in section.Children)
        {
            if (_readers.TryGetValue(child.Key, out Action<SettingValue, T>? read))
            {
                read(new SettingValue(child, prefix + Canonical(child.Key), problems), target);
            }
            else if (_renamed.TryGetValue(child.Key, out string? now))
            {
                problems.Add(new HostLinkSettingsProblem(prefix + child.Key, $"is now called {prefix + now}; rename the key"));
            }
            else
            {
                problems.Add(new HostLinkSettingsProblem(prefix + child.Key, Unknown(child.Key, prefix, suggest)));
            }
        }
    }

    public IEnumerator<string> GetEnumerator() => _names.GetEnumerator();

    System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();

    private string Canonical(string key) => _names.First(n => n.Equals(key, StringComparison.OrdinalIgnoreCase));

    private string Unknown(string key, string prefix, Func<string, string?>? suggest)
    {
        string? suggestion = suggest?.Invoke(key) ?? _names
            .Select(n => (Name: n, Distance: EditDistance(key.ToUpperInvariant(), n.ToUpperInvariant())))
            .Where(c => c.Distance <= Math.Max(1, c.Name.Length / 4))
            .OrderBy(c => c.Distance)
            .Select(c => prefix + c.Name)
            .FirstOrDefault();
        return suggestion is null
            ? $"not {_what} (known: {string.Join(", ", _names)})"
            : $"not {_what}; did you mean {suggestion}?";
    }

    private static int EditDistance(string a, string b)
    {
        int[] previous = Enumerable.Range(0, b.Length + 1).ToArray();
        int[] current = new int[b.Length + 1];
        for (int i = 1; i <= a.Length; i++)
        {
            current[0] = i;
            for (int j = 1; j <= b.Length; j++)
            {
                int substitute = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
                current[j] = Math.Min(substitute, Math.Min(previous[j], current[j - 1]) + 1);
            }

            (previous, current) = (current, previous);
        }

        return previous[b.Length];
    }
}
