namespace OmronHostLink.Gateway.Configuration;

/// <summary>The names the gateway is known by outside the process.</summary>
internal static class GatewayNames
{
    /// <summary>
    /// The service: the Windows service name (deploy/install-service.ps1 registers the service under it), OpenTelemetry's
    /// <c>service.name</c>, and the state directory's name under <c>%ProgramData%</c>.
    /// </summary>
    public const string Service = "OmronHostLink.Gateway";

    /// <summary>
    /// The meter of the gateway's own instruments
    /// (<c>dotnet-counters monitor -n OmronHostLink.Gateway --counters OmronHostLink.Gateway</c>).
    /// </summary>
    public const string Meter = "OmronHostLink.Gateway";
}
