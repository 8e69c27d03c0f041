using OmronHostLink.Transports;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// Checks the <c>HostLink</c> section before anything starts, naming each bad field by its configuration path
/// (<c>HostLink:Links:line1:Groups:levels:Address</c>, or a tag file's path and line) so the message points at the line
/// to fix; every group is checked as the gateway will poll it, and so is every rule the outputs add (<see cref="IGroupRule"/>).
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
internal sealed class GatewayOptionsValidator(GatewayConfiguration gateway) : SectionValidator<GatewayOptions>(gateway, GatewayOptions.SectionName)
{
    /// <summary>The longest poll interval or retry wait the library's watch accepts.</summary>
    private static readonly TimeSpan LongestWait = TimeSpan.FromDays(1);

    /// <inheritdoc/>
    protected override void Check(GatewayOptions options, List<string> failures)
    {
        const string root = GatewayOptions.SectionName + ":Links";
        if (!options.Links.Values.Any(l => l is { Enabled: true }))
        {
            failures.Add($"{root}: no enabled link is configured; add at least one link with a Serial or Tcp setting and a poll group.");
        }

        IReadOnlyList<IGroupRule> rules = Gateway.GroupRules;
        foreach ((string linkName, LinkOptions? link) in options.Links)
        {
            if (link is null || !link.Enabled)
            {
                continue;
            }

            ValidateLink(linkName, $"{root}:{linkName}", link, rules, failures);
        }
    }

    /// <summary>Why <paramref name="unit"/> is no unit number; null when it is one.</summary>
    internal static string? UnitProblem(int unit)
        => HostLinkRules.CheckUnitNumber(unit) is { } problem ? $"{problem}." : null;

    /// <summary>Why <paramref name="interval"/> is no poll interval; null when it is one.</summary>
    internal static string? IntervalProblem(TimeSpan interval)
        => interval <= TimeSpan.Zero || interval > LongestWait ? $"must be more than 0 and at most 1 day; it is {interval}." : null;

    /// <summary>Why <paramref name="log"/> is no log mode; null when it is one.</summary>
    internal static string? LogProblem(string? log)
        => !Enum.TryParse(log, ignoreCase: true, out PollLogMode mode) || !Enum.IsDefined(mode) || int.TryParse(log, out _)
            ? $"'{log}' is not EveryPoll or OnChange."
            : null;

    private static void ValidateLink(string linkName, string path, LinkOptions link, IReadOnlyList<IGroupRule> rules, List<string> failures)
    {
        // The client's keys were checked with the section as written, by the library's one validation.
        failures.AddRange(link.TagFileProblems.Select(p => $"{path}:{p}"));
        // A URL or a dotted number that is no IPv4 address would be looked up as a host name, and retried for ever.
        if (link.Client.Tcp.Host is { Length: > 0 } host && HostSyntax.Problem(host.Trim()) is { } problem)
        {
            failures.Add($"{path}:Tcp '{host}' does not name a host: {problem}.");
        }

        if (link.CommandSet == HostLinkCommandSet.Fins && link.Client.HostLinkCompatibleMode is { } mode)
        {
            failures.Add($"{path}:HostLinkCompatibleMode {mode} checks how a unit frames C-mode answers; with CommandSet Fins it would be ignored. Remove it, or set CommandSet CMode.");
        }

        if (link.Backoff is null)
        {
            failures.Add($"{path}:Backoff is missing.");
        }
        else
        {
            if (link.Backoff.Initial <= TimeSpan.Zero || link.Backoff.Initial > LongestWait)
            {
                failures.Add($"{path}:Backoff:Initial must be more than 0 and at most 1 day; it is {link.Backoff.Initial}.");
            }

            if (link.Backoff.Max < link.Backoff.Initial)
            {
                failures.Add($"{path}:Backoff:Max ({link.Backoff.Max}) must be at least Backoff:Initial ({link.Backoff.Initial}).");
            }
            else if (link.Backoff.Max > LongestWait)
            {
                failures.Add($"{path}:Backoff:Max must be at most 1 day; it is {link.Backoff.Max}.");
            }
        }

        DemotionOptions.Validate(path, link.Demotion, failures);
        if (link.Groups.Count == 0 && link.TagFileProblems.Count == 0)
        {
            failures.Add($"{path}:Groups: the link has no poll group.");
        }

        foreach (IGroupRule rule in rules)
        {
            rule.CheckLink(linkName, path, failures);
        }

        foreach (ConfiguredGroup group in ConfiguredGroup.Of(linkName, link))
        {
            // The outputs' rules judge groups the section accepts: a group that cannot be read has one problem to fix first.
            if (ValidateGroup(group, link.CommandSet, failures))
            {
                foreach (IGroupRule rule in rules)
                {
                    rule.CheckGroup(group, link, failures);
                }
            }
        }
    }

    /// <summary>Adds the group's problems to <paramref name="failures"/>; true when it has none.</summary>
    private static bool ValidateGroup(ConfiguredGroup configured, HostLinkCommandSet protocol, List<string> failures)
    {
        int before = failures.Count;
        PollGroupOptions group = configured.Options;
        if (UnitProblem(group.Unit) is { } unitProblem)
        {
            failures.Add($"{configured.KeyOf("Unit")}: {unitProblem}");
        }

        if (IntervalProblem(group.Interval) is { } intervalProblem)
        {
            failures.Add($"{configured.KeyOf("Interval")} {intervalProblem}");
        }

        if (LogProblem(group.Log) is { } logProblem)
        {
            failures.Add($"{configured.KeyOf("Log")} {logProblem}");
        }

        bool typeOk = PollValueTypes.TryParse(group.Type, out PlcValueType type);
        if (!typeOk)
        {
            failures.Add($"{configured.KeyOf("Type")} '{group.Type}' is not one of {PollValueTypes.Names}.");
        }

        int maxCount = type == PlcValueType.String ? 20000 : 10000;
        if (group.Count < 1 || group.Count > maxCount)
        {
            failures.Add($"{configured.KeyOf("Count")} must be 1-{maxCount}; it is {group.Count}.");
            return false;
        }

        string addressKey = configured.KeyOf("Address");
        if (!PlcAddress.TryParse(group.Address, out PlcAddress address))
        {
            failures.Add(string.IsNullOrWhiteSpace(group.Address)
                ? $"{addressKey} is empty; set the first address to read, e.g. D100."
                : $"{addressKey} {Reason(group.Address)}");
            return false;
        }

        if (!typeOk)
        {
            return false;
        }

        if (type == PlcValueType.Bit)
        {
            if (PollValueTypes.IsCompletionFlag(type, address))
            {
                if (group.Count != 1)
                {
                    failures.Add($"{configured.KeyOf("Count")} must be 1 for a timer/counter completion flag ({address}); it is {group.Count}.");
                    return false;
                }
            }
            else if (!address.IsBit)
            {
                failures.Add($"{addressKey} {address} names a word; type bit needs a bit address such as {address}.00 (or a timer/counter number).");
                return false;
            }
        }
        else if (address.IsBit)
        {
            failures.Add($"{addressKey} {address} names a bit; type {type.ToString().ToLowerInvariant()} needs a word address such as {address.AsWord()} (or use type bit).");
            return false;
        }

        try
        {
            address.AsWord().EnsureRange(PollValueTypes.WordCount(type, address, group.Count), protocol, forWrite: false);
        }
        catch (ArgumentException e)
        {
            failures.Add($"{configured.Key}: {group.Count} × {type.ToString().ToLowerInvariant()} from {address}: {ErrorText.Of(e)}");
        }

        return failures.Count == before;
    }

    private static string Reason(string text)
    {
        try
        {
            PlcAddress.Parse(text);
            return $"'{text}' is not valid.";
        }
        catch (FormatException e)
        {
            return e.Message;
        }
    }
}
