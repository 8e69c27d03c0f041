using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Options;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// The configuration as the gateway reads it, once per host: the <c>HostLink</c> section bound once (its links' client
/// keys, its tag files read once), so that every check sees the links and groups the gateway polls; each section
/// checked once as written against its options class (<see cref="ConfigurationSchema"/>); the rules the outputs add to
/// every link and group (<see cref="IGroupRule"/>); and each section's verdict, kept so that a section is judged once
/// however often its options are asked for.
/// </summary>
/// <param name="root">The whole configuration.</param>
internal sealed class GatewayConfiguration(IConfiguration root)
{
    private readonly object _gate = new();
    private readonly Dictionary<string, IReadOnlyList<string>> _written = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<string, ValidateOptionsResult> _verdicts = new(StringComparer.OrdinalIgnoreCase);
    private readonly List<IGroupRule> _rules = [];
    private GatewayOptions? _hostLink;

    /// <summary>The whole configuration.</summary>
    public IConfiguration Root { get; } = root;

    /// <summary>The <c>HostLink</c> section, bound once: the links and groups the gateway polls and every check sees.</summary>
    public GatewayOptions HostLink
    {
        get
        {
            lock (_gate)
            {
                if (_hostLink is null)
                {
                    var options = new GatewayOptions();
                    LinkClients.Bind(Root.GetSection(GatewayOptions.SectionName), options);
                    _hostLink = options;
                }

                return _hostLink;
            }
        }
    }

    /// <summary>The rules the outputs add to every enabled link and its groups, in the order they were added.</summary>
    public IReadOnlyList<IGroupRule> GroupRules
    {
        get
        {
            lock (_gate)
            {
                return _rules.ToArray();
            }
        }
    }

    /// <summary>Adds a rule for every link and group, once however many outputs add it.</summary>
    public void AddGroupRule(IGroupRule rule)
    {
        ArgumentNullException.ThrowIfNull(rule);
        lock (_gate)
        {
            if (!_rules.Any(r => r.GetType() == rule.GetType()))
            {
                _rules.Add(rule);
            }
        }
    }

    /// <summary>Whether an optional section (an output) is on: it is there, and its <c>Enabled</c> is not false.</summary>
    public bool IsEnabled(string section)
    {
        IConfigurationSection s = Root.GetSection(section);
        return s.Exists() && !(bool.TryParse(s["Enabled"], out bool enabled) && !enabled);
    }

    /// <summary>Binds <paramref name="section"/> to <paramref name="options"/>, durations read with the library's grammar.</summary>
    public void Bind(string section, object options) => ConfigurationSchema.Bind(Root.GetSection(section), options);

    /// <summary>The problems of <paramref name="section"/> as written, read as <paramref name="options"/>; found once.</summary>
    public IReadOnlyList<string> Written(string section, Type options)
    {
        lock (_gate)
        {
            if (!_written.TryGetValue(section, out IReadOnlyList<string>? problems))
            {
                problems = ConfigurationSchema.Check(Root.GetSection(section), options);
                _written[section] = problems;
            }

            return problems;
        }
    }

    /// <summary>
    /// The verdict on <paramref name="section"/>: found by <paramref name="check"/> the first time it is asked for, the
    /// same afterwards (a section's options are bound from the same configuration each time).
    /// </summary>
    public ValidateOptionsResult Verdict(string section, Func<ValidateOptionsResult> check)
    {
        ArgumentNullException.ThrowIfNull(check);
        lock (_gate)
        {
            if (_verdicts.TryGetValue(section, out ValidateOptionsResult? verdict))
            {
                return verdict;
            }
        }

        // Outside the lock: a check may read the HostLink binding or the section as written.
        ValidateOptionsResult result = check();
        lock (_gate)
        {
            return _verdicts.TryAdd(section, result) ? result : _verdicts[section];
        }
    }
}
