namespace OmronHostLink;

/// <summary>
/// One setting of a settings section, declared once: its key (and the key it had before a rename), how its text is
/// read, the rule its value obeys, and how it applies to the options it configures — which is also where its default
/// comes from: the value a new <typeparamref name="TOptions"/> holds. The section's keys, validation and mapping to
/// the options all iterate these declarations (<see cref="HostLinkClientSettings"/>, <see cref="HostLinkSerialSettings"/>).
/// </summary>
/// <typeparam name="TSettings">The settings section (<see cref="HostLinkClientSettings"/>).</typeparam>
/// <typeparam name="TOptions">What the section configures (<see cref="HostLinkClientOptions"/>).</typeparam>
internal abstract class Setting<TSettings, TOptions>
    where TOptions : new()
{
    private protected Setting(string key) => Key = key;

    /// <summary>The key in configuration, also the name of the settings' and the options' property.</summary>
    public string Key { get; }

    /// <summary>The key this setting had before it was renamed; reading it says what it is now called.</summary>
    public string? FormerKey { get; protected set; }

    /// <summary>Reads the key's value into <paramref name="settings"/>; a value that cannot be used is a problem at its key.</summary>
    public abstract void Read(SettingValue value, TSettings settings);

    /// <summary>What is wrong with the value <paramref name="settings"/> hold, or null (also when unset).</summary>
    public abstract string? Check(TSettings settings);

    /// <summary>Sets the options from a set value; an unset one leaves the options' default.</summary>
    public abstract void Apply(TSettings settings, TOptions options);
}

/// <summary>A setting whose settings property has type <typeparamref name="TValue"/> (null: unset).</summary>
internal sealed class Setting<TSettings, TOptions, TValue> : Setting<TSettings, TOptions>
    where TOptions : new()
{
    private readonly Func<TSettings, TValue?> _get;
    private readonly Action<TSettings, TValue?> _set;
    private readonly Func<SettingValue, TValue?> _read;
    private readonly Func<TValue, string?> _rule;
    private readonly Func<TOptions, TValue> _current;
    private readonly Action<TOptions, TValue> _apply;

    public Setting(
        string key,
        Func<TSettings, TValue?> get,
        Action<TSettings, TValue?> set,
        Func<SettingValue, TValue?> read,
        Func<TValue, string?> rule,
        Func<TOptions, TValue> current,
        Action<TOptions, TValue> apply)
        : base(key)
    {
        (_get, _set, _read, _rule, _current, _apply) = (get, set, read, rule, current, apply);
    }

    /// <summary>Declares the key the setting had before: reading it is a problem that names the key it has now.</summary>
    public Setting<TSettings, TOptions, TValue> Renamed(string formerKey)
    {
        FormerKey = formerKey;
        return this;
    }

    /// <summary>The default: what a new <typeparamref name="TOptions"/> holds.</summary>
    public TValue Default => _current(new TOptions());

    public override void Read(SettingValue value, TSettings settings)
    {
        TValue? read = _read(value);
        if (read is not null)
        {
            _set(settings, read);
        }
    }

    public override string? Check(TSettings settings) => _get(settings) is { } value ? _rule(value) : null;

    public override void Apply(TSettings settings, TOptions options)
    {
        if (_get(settings) is { } value)
        {
            _apply(options, value);
        }
    }
}

/// <summary>Declares the settings of one section (a file aliases it: <c>using ClientSetting = Declare&lt;…&gt;</c>).</summary>
internal static class Declare<TSettings, TOptions>
    where TOptions : new()
{
    /// <summary>A setting of a value type (<c>int?</c>, <c>bool?</c>, <c>TimeSpan?</c>, an enum); the options' value may be null (no default).</summary>
    public static Setting<TSettings, TOptions, T?> Value<T>(
        string key,
        Func<TSettings, T?> get,
        Action<TSettings, T?> set,
        Func<SettingValue, T?> read,
        Func<T, string?>? rule,
        Func<TOptions, T?> current,
        Action<TOptions, T> apply)
        where T : struct
        => new(key, get, set, read, v => rule?.Invoke(v!.Value), current, (o, v) => apply(o, v!.Value));

    /// <summary>A setting of a reference type (text, a map); the options' value may be null (no default).</summary>
    public static Setting<TSettings, TOptions, T> Reference<T>(
        string key,
        Func<TSettings, T?> get,
        Action<TSettings, T?> set,
        Func<SettingValue, T?> read,
        Func<T, string?>? rule,
        Func<TOptions, T?> current,
        Action<TOptions, T> apply)
        where T : class
        => new(key, get, set, read, v => rule?.Invoke(v), o => current(o)!, apply);
}
