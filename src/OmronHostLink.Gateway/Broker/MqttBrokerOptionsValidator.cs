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
    /// <param name="now">The time a client certificate must be valid at; the system's clock by default.</param>
    public static void Validate(MqttBrokerOptions options, string section, List<string> failures, DateTimeOffset? now = null)
    {
        DateTimeOffset at = now ?? DateTimeOffset.UtcNow;
        if (options.Servers is { Count: > 0 } servers)
        {
            if (!string.IsNullOrWhiteSpace(options.Host) || options.Port is not null)
            {
                string set = !string.IsNullOrWhiteSpace(options.Host) ? "Host" : "Port";
                failures.Add($"{section}:{set} is set beside {section}:Servers; give either one broker ({section}:Host, {section}:Port) or the list ({section}:Servers:0:Host, {section}:Servers:1:Host, …), not both.");
            }

            var seen = new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase);
            for (int i = 0; i < servers.Count; i++)
            {
                string key = $"{section}:Servers:{i}";
                MqttServerOptions server = servers[i] ?? new MqttServerOptions();
                int problems = failures.Count;
                ValidateHost(server.Host, key + ":Host", key + ":Port", failures);
                ValidatePort(server.Port, key + ":Port", failures);
                if (server.Tls is { } tls)
                {
                    ValidateTls(tls, key + ":Tls", failures, at);
                }

                MqttServer effective = options.ServersInEffect(section)[i];
                if (failures.Count == problems && seen.TryGetValue(effective.Address, out int first))
                {
                    failures.Add($"{key} names {effective.Address} again ({section}:Servers:{first} does already); each broker is listed once.");
                }

                seen.TryAdd(effective.Address, i);
            }
        }
        else
        {
            ValidateHost(options.Host, $"{section}:Host", $"{section}:Port", failures, section);
            ValidatePort(options.Port, $"{section}:Port", failures);
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

        ValidateTls(options.Tls, $"{section}:Tls", failures, at);
    }

    private static void ValidateHost(string? host, string key, string portKey, List<string> failures, string? section = null)
    {
        if (string.IsNullOrWhiteSpace(host))
        {
            string list = section is null ? "" : $" (or list several in {section}:Servers)";
            failures.Add($"{key} is empty; set the broker's host name or address (e.g. 127.0.0.1 or broker.plant.local){list}.");
        }
        else if (host.Any(char.IsWhiteSpace) || host.Contains('/', StringComparison.Ordinal) || host.Count(c => c == ':') == 1)
        {
            failures.Add($"{key} '{host}' is not a host name or address (no scheme, no port: the port is {portKey}).");
        }
        else if (HostSyntax.Problem(host) is { } hostProblem)
        {
            failures.Add($"{key} '{host}' is not a host name or address: {hostProblem}.");
        }
    }

    private static void ValidatePort(int? port, string key, List<string> failures)
    {
        if (port is { } p && p is < 1 or > 65535)
        {
            failures.Add($"{key} must be 1-65535; it is {p}.");
        }
    }

    private static void ValidateTls(MqttTlsOptions? tls, string key, List<string> failures, DateTimeOffset now)
    {
        if (tls is null)
        {
            return;
        }

        if (!tls.Enabled)
        {
            string? set = !string.IsNullOrEmpty(tls.CaFile) ? "CaFile"
                : tls.AllowUntrustedCertificates ? "AllowUntrustedCertificates"
                : !string.IsNullOrEmpty(tls.ServerName) ? "ServerName"
                : !string.IsNullOrEmpty(tls.ClientCertificateFile) ? "ClientCertificateFile"
                : !string.IsNullOrEmpty(tls.ClientKeyFile) ? "ClientKeyFile"
                : null;
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

        if (!string.IsNullOrEmpty(tls.ClientCertificateFile))
        {
            if (ClientCertificate.Problem(tls, key, now) is { } certificateProblem)
            {
                failures.Add(certificateProblem);
            }
        }
        else if (!string.IsNullOrEmpty(tls.ClientKeyFile))
        {
            failures.Add($"{key}:ClientKeyFile is set without {key}:ClientCertificateFile; set the certificate the key belongs to.");
        }
    }
}
