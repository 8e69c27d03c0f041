using System.Net;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// Checks the <c>Status</c> section: an IP address (no name is looked up), a port, and a token wherever the page is
/// reachable from another machine — strong enough, and carried by an <c>Authorization</c> header as it is.
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
internal sealed class StatusOptionsValidator(GatewayConfiguration gateway) : SectionValidator<StatusOptions>(gateway, StatusOptions.SectionName)
{
    private static readonly TimeSpan ShortestRefresh = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan LongestRefresh = TimeSpan.FromSeconds(10);

    /// <inheritdoc/>
    protected override bool IsOn(StatusOptions options) => Gateway.IsEnabled(Section);

    /// <inheritdoc/>
    protected override void Check(StatusOptions options, List<string> failures)
    {
        const string root = StatusOptions.SectionName;
        IPAddress? address = options.IPAddress;
        if (address is null)
        {
            failures.Add($"{root}:Address '{options.Address}' is not an IP address; write 127.0.0.1 (this machine only, the default), an address of this machine, or 0.0.0.0 (every interface).");
        }

        if (options.Port is < 1 or > 65535)
        {
            failures.Add($"{root}:Port must be 1-65535; it is {options.Port}.");
        }

        if (options.HasToken)
        {
            string token = options.AccessToken!;
            if (token.Length < StatusOptions.ShortestToken)
            {
                failures.Add($"{root}:AccessToken has {token.Length} characters; use at least {StatusOptions.ShortestToken} (a random one: openssl rand -hex 16).");
            }
            else if (!token.All(IsTokenCharacter))
            {
                failures.Add($"{root}:AccessToken holds a character an Authorization header cannot carry; use letters, digits and - . _ ~ + / (a random one: openssl rand -hex 16).");
            }
        }
        else if (address is not null && !IPAddress.IsLoopback(address))
        {
            failures.Add($"{root}:AccessToken is required when {root}:Address is {address} (not a loopback address): anyone who reaches port {options.Port} could read the page. Set one of at least {StatusOptions.ShortestToken} characters (in the environment: Status__AccessToken), or leave {root}:Address at {StatusOptions.DefaultAddress}.");
        }

        if (options.TraceFrames is < 10 or > 10_000)
        {
            failures.Add($"{root}:TraceFrames must be 10-10000; it is {options.TraceFrames}.");
        }

        if (options.RefreshInterval < ShortestRefresh || options.RefreshInterval > LongestRefresh)
        {
            failures.Add($"{root}:RefreshInterval must be 100ms to 10s; it is {options.RefreshInterval.TotalMilliseconds:0.###} ms.");
        }
    }

    /// <summary>A character of a bearer token (RFC 6750's b64token, its trailing '=' included).</summary>
    private static bool IsTokenCharacter(char c) => char.IsAsciiLetterOrDigit(c) || c is '-' or '.' or '_' or '~' or '+' or '/' or '=';
}
