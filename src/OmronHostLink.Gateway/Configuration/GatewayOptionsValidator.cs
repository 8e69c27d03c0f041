using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Options;
using OmronHostLink.Transports;
using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// Checks the <c>HostLink</c> section before anything starts, naming each bad field by its configuration path
/// (<c>HostLink:Links:line1:Groups:levels:Address</c>) so the message points at the line to fix.
/// </summary>
public sealed class GatewayOptionsValidator : IValidateOptions<GatewayOptions>
{
    /// <summary>The longest poll interval or retry wait the library's watch accepts.</summary>
    private static readonly TimeSpan LongestWait = TimeSpan.FromDays(1);

    private readonly IConfiguration? _configuration;

    /// <summary>Checks the bound options only.</summary>
    public GatewayOptionsValidator()
    {
    }

    /// <summary>Checks the section as written first (<see cref="ConfigurationSchema"/>), then the bound options.</summary>
    /// <param name="configuration">The configuration the options are bound from.</param>
    public GatewayOptionsValidator(IConfiguration configuration)
    {
        _configuration = configuration;
    }

    /// <inheritdoc/>
    public ValidateOptionsResult Validate(string? name, GatewayOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        if (_configuration is not null
            && ConfigurationSchema.Check(_configuration.GetSection(GatewayOptions.SectionName), typeof(GatewayOptions)) is { Count: > 0 } written)
        {
            // The bound options miss what could not be read; judging them would only add consequences of these.
            return ValidateOptionsResult.Fail(written);
        }

        var failures = new List<string>();
        const string root = GatewayOptions.SectionName + ":Links";
        if (!options.Links.Values.Any(l => l is { Enabled: true }))
        {
            failures.Add($"{root}: no enabled link is configured; add at least one link with a Serial or Tcp setting and a poll group.");
        }

        foreach ((string linkName, LinkOptions? link) in options.Links)
        {
            if (link is null || !link.Enabled)
            {
                continue;
            }

            ValidateLink($"{root}:{linkName}", link, failures);
        }

        return failures.Count == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
    }

    private static void ValidateLink(string path, LinkOptions link, List<string> failures)
    {
        failures.AddRange(link.TagFileProblems.Select(p => $"{path}:{p}"));

        // The client's keys: the library's one validation, as the DI package reports it.
        failures.AddRange(link.Client.Validate().Select(p => p.Key.Length == 0 ? $"{path}: {p.Message}." : $"{path}:{p.Key}: {p.Message}."));

        // A URL or a dotted number that is no IPv4 address would be looked up as a host name, and retried for ever.
        if (link.Client.Tcp.Host is { Length: > 0 } host && HostSyntax.Problem(host.Trim()) is { } problem)
        {
            failures.Add($"{path}:Tcp '{host}' does not name a host: {problem}.");
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
        if (link.Groups.Count == 0)
        {
            failures.Add($"{path}:Groups: the link has no poll group.");
        }

        foreach ((string groupName, PollGroupOptions? group) in link.Groups)
        {
            if (group is not null)
            {
                ValidateGroup($"{path}:Groups:{groupName}", group, link.CommandSet, failures);
            }
        }
    }

    private static void ValidateGroup(string path, PollGroupOptions group, HostLinkCommandSet protocol, List<string> failures)
    {
        if (HostLinkRules.CheckUnitNumber(group.Unit) is { } unitProblem)
        {
            failures.Add($"{path}:Unit: {unitProblem}.");
        }

        if (group.Interval <= TimeSpan.Zero || group.Interval > LongestWait)
        {
            failures.Add($"{path}:Interval must be more than 0 and at most 1 day; it is {group.Interval}.");
        }

        if (!Enum.TryParse(group.Log, ignoreCase: true, out PollLogMode mode) || !Enum.IsDefined(mode) || int.TryParse(group.Log, out _))
        {
            failures.Add($"{path}:Log '{group.Log}' is not EveryPoll or OnChange.");
        }

        bool typeOk = PollValueTypes.TryParse(group.Type, out PlcValueType type);
        if (!typeOk)
        {
            failures.Add($"{path}:Type '{group.Type}' is not one of {PollValueTypes.Names}.");
        }

        int maxCount = type == PlcValueType.String ? 20000 : 10000;
        if (group.Count < 1 || group.Count > maxCount)
        {
            failures.Add($"{path}:Count must be 1-{maxCount}; it is {group.Count}.");
            return;
        }

        if (!PlcAddress.TryParse(group.Address, out PlcAddress address))
        {
            failures.Add(string.IsNullOrWhiteSpace(group.Address)
                ? $"{path}:Address is empty; set the first address to read, e.g. D100."
                : $"{path}:Address {Reason(group.Address)}");
            return;
        }

        if (!typeOk)
        {
            return;
        }

        if (type == PlcValueType.Bit)
        {
            if (PollValueTypes.IsCompletionFlag(type, address))
            {
                if (group.Count != 1)
                {
                    failures.Add($"{path}:Count must be 1 for a timer/counter completion flag ({address}); it is {group.Count}.");
                    return;
                }
            }
            else if (!address.IsBit)
            {
                failures.Add($"{path}:Address {address} names a word; type bit needs a bit address such as {address}.00 (or a timer/counter number).");
                return;
            }
        }
        else if (address.IsBit)
        {
            failures.Add($"{path}:Address {address} names a bit; type {type.ToString().ToLowerInvariant()} needs a word address such as {address.AsWord()} (or use type bit).");
            return;
        }

        try
        {
            address.AsWord().EnsureRange(PollValueTypes.WordCount(type, address, group.Count), protocol, forWrite: false);
        }
        catch (ArgumentException e)
        {
            failures.Add($"{path}: {group.Count} × {type.ToString().ToLowerInvariant()} from {address}: {StripParamName(e)}");
        }
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

    // ArgumentException.Message appends " (Parameter 'x')"; the path already names the field.
    private static string StripParamName(ArgumentException e)
    {
        string message = e.Message;
        int at = e.ParamName is null ? -1 : message.LastIndexOf(" (Parameter '", StringComparison.Ordinal);
        return at >= 0 ? message.Substring(0, at) : message;
    }
}
