using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// The rules of a broker connection (<see cref="MqttBrokerOptions"/>), the same in every section that has one; each
/// failure names its key below the section's.
/// </summary>
internal static class MqttBrokerOptionsValidator
{
    /// <summary>Adds the problems of the broker settings of <paramref name="options"/> to <paramref name="failures"/>.</summary>
    /// <param name="options">The section's options.</param>
    /// <param name="section">The section's key (<c>Mqtt</c>, <c>Sparkplug</c>), which starts every key named.</param>
    /// <param name="failures">Where the problems go, one message each.</param>
    public static void Validate(MqttBrokerOptions options, string section, List<string> failures)
    {
        if (string.IsNullOrWhiteSpace(options.Host))
        {
            failures.Add($"{section}:Host is empty; set the broker's host name or address (e.g. 127.0.0.1 or broker.plant.local).");
        }
        else if (options.Host.Any(char.IsWhiteSpace) || options.Host.Contains('/', StringComparison.Ordinal) || options.Host.Count(c => c == ':') == 1)
        {
            failures.Add($"{section}:Host '{options.Host}' is not a host name or address (no scheme, no port: the port is {section}:Port).");
        }
        else if (HostSyntax.Problem(options.Host) is { } hostProblem)
        {
            failures.Add($"{section}:Host '{options.Host}' is not a host name or address: {hostProblem}.");
        }

        if (options.Port is { } port && port is < 1 or > 65535)
        {
            failures.Add($"{section}:Port must be 1-65535; it is {port}.");
        }

        if (!string.IsNullOrEmpty(options.Password) && string.IsNullOrEmpty(options.Username))
        {
            failures.Add($"{section}:Password is set without {section}:Username.");
        }

        // CONNECT carries the keep-alive as a 16-bit count of seconds. 0 means no keep-alive at all (MQTTnet then sends
        // no PINGREQ and the broker never times the client out): a broker that vanished without closing the connection
        // would go unnoticed, and so would this client to the broker, which would never publish its will.
        if (options.KeepAlive < TimeSpan.FromSeconds(1) || options.KeepAlive > TimeSpan.FromSeconds(ushort.MaxValue))
        {
            failures.Add($"{section}:KeepAlive must be 1s to 18:12:15 (whole seconds); it is {options.KeepAlive}.");
        }
        else if (options.KeepAlive.Ticks % TimeSpan.TicksPerSecond != 0)
        {
            failures.Add($"{section}:KeepAlive is sent in whole seconds; {options.KeepAlive} is not.");
        }

        if (options.Timeout <= TimeSpan.Zero)
        {
            failures.Add($"{section}:Timeout must be more than 0; it is {options.Timeout}.");
        }

        if (options.Reconnect is null)
        {
            failures.Add($"{section}:Reconnect is missing.");
        }
        else
        {
            if (options.Reconnect.Initial <= TimeSpan.Zero)
            {
                failures.Add($"{section}:Reconnect:Initial must be more than 0; it is {options.Reconnect.Initial}.");
            }

            if (options.Reconnect.Max < options.Reconnect.Initial)
            {
                failures.Add($"{section}:Reconnect:Max ({options.Reconnect.Max}) must be at least Reconnect:Initial ({options.Reconnect.Initial}).");
            }
        }

        ValidateTls(options.Tls, $"{section}:Tls", failures);
    }

    private static void ValidateTls(MqttTlsOptions? tls, string key, List<string> failures)
    {
        if (tls is null)
        {
            return;
        }

        if (!tls.Enabled)
        {
            string? set = !string.IsNullOrEmpty(tls.CaFile) ? "CaFile" : tls.AllowUntrustedCertificates ? "AllowUntrustedCertificates" : !string.IsNullOrEmpty(tls.ServerName) ? "ServerName" : null;
            if (set is not null)
            {
                failures.Add($"{key}:Enabled is false but {set} is set; set {key}:Enabled to true to use TLS.");
            }

            return;
        }

        if (!string.IsNullOrEmpty(tls.ServerName) && HostSyntax.Problem(tls.ServerName) is { } nameProblem)
        {
            failures.Add($"{key}:ServerName '{tls.ServerName}' is not a host name or address: {nameProblem}.");
        }

        if (!string.IsNullOrEmpty(tls.CaFile))
        {
            if (!File.Exists(tls.CaFile))
            {
                failures.Add($"{key}:CaFile '{tls.CaFile}' does not exist (relative paths start at the working directory, {Environment.CurrentDirectory}).");
            }
            else
            {
                try
                {
                    foreach (System.Security.Cryptography.X509Certificates.X509Certificate2 certificate in MqttClientOptionsFactory.LoadAuthorities(tls.CaFile))
                    {
                        certificate.Dispose();
                    }
                }
                catch (Exception e) when (e is InvalidOperationException or System.Security.Cryptography.CryptographicException or IOException or UnauthorizedAccessException)
                {
                    failures.Add($"{key}:CaFile '{tls.CaFile}' cannot be read as PEM certificates: {e.Message}");
                }
            }

            if (tls.AllowUntrustedCertificates)
            {
                failures.Add($"{key}: set either CaFile or AllowUntrustedCertificates, not both (AllowUntrustedCertificates turns every check off).");
            }
        }
    }
}
