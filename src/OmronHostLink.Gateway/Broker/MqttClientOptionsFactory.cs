using System.Net.Security;
using System.Security.Cryptography.X509Certificates;
using MQTTnet;
using MQTTnet.Protocol;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// Turns a broker connection (<see cref="MqttBrokerOptions"/>) into MQTTnet's client options: server, client id,
/// keep-alive, timeout, credentials and TLS. Each output adds its protocol version, session and last will.
/// </summary>
internal static class MqttClientOptionsFactory
{
    /// <summary>Starts the client options of a broker connection; the CA file is read here.</summary>
    /// <param name="options">The validated options.</param>
    /// <param name="section">The section's key (<c>Mqtt</c>, <c>Sparkplug</c>), named in why a certificate was refused.</param>
    /// <param name="certificateRejected">Told why the broker's certificate was refused (TLS only).</param>
    /// <returns>The builder, for the output to add its protocol version, session and will to.</returns>
    public static MqttClientOptionsBuilder Create(MqttBrokerOptions options, string section, Action<string>? certificateRejected = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        MqttClientOptionsBuilder builder = new MqttClientOptionsBuilder()
            .WithTcpServer(options.Host, options.PortOrDefault)
            .WithClientId(options.ClientIdOrDefault)
            .WithKeepAlivePeriod(options.KeepAlive)
            .WithTimeout(options.Timeout);
        if (!string.IsNullOrEmpty(options.Username))
        {
            builder = builder.WithCredentials(options.Username, options.Password ?? "");
        }

        if (options.Tls.Enabled)
        {
            MqttTlsOptions tls = options.Tls;
            X509Certificate2Collection? authorities = string.IsNullOrEmpty(tls.CaFile) ? null : LoadAuthorities(tls.CaFile);
            builder = builder.WithTlsOptions(o =>
            {
                o.UseTls()
                    .WithTargetHost(string.IsNullOrEmpty(tls.ServerName) ? options.Host : tls.ServerName)
                    .WithCertificateValidationHandler(e =>
                    {
                        string? why = CertificateProblem(e.Certificate, e.Chain, e.SslPolicyErrors, authorities, tls.AllowUntrustedCertificates, section + ":Tls");
                        if (why is not null)
                        {
                            certificateRejected?.Invoke(why);
                        }

                        return why is null;
                    });
            });
        }

        return builder;
    }

    /// <summary>The MQTTnet level for 0, 1 or 2.</summary>
    public static MqttQualityOfServiceLevel QualityOfService(int qos) => qos switch
    {
        0 => MqttQualityOfServiceLevel.AtMostOnce,
        2 => MqttQualityOfServiceLevel.ExactlyOnce,
        _ => MqttQualityOfServiceLevel.AtLeastOnce,
    };

    /// <summary>Reads the CA certificates of a PEM file.</summary>
    /// <exception cref="InvalidOperationException">The file holds no certificate.</exception>
    public static X509Certificate2Collection LoadAuthorities(string path)
    {
        var authorities = new X509Certificate2Collection();
        authorities.ImportFromPemFile(path);
        if (authorities.Count == 0)
        {
            throw new InvalidOperationException($"{path} holds no PEM certificate (-----BEGIN CERTIFICATE-----).");
        }

        return authorities;
    }

    /// <summary>
    /// Checks the broker's certificate: null when it is accepted, otherwise why not, naming the keys below
    /// <paramref name="tlsKey"/> (<c>Mqtt:Tls</c>) that change the verdict. Without CA certificates the platform's
    /// verdict stands (system roots, name, dates). With them, the name must still match and the chain must end at one
    /// of them: nothing else is trusted.
    /// </summary>
    private static string? CertificateProblem(X509Certificate? certificate, X509Chain? chain, SslPolicyErrors errors, X509Certificate2Collection? authorities, bool allowUntrusted, string tlsKey)
    {
        if (allowUntrusted)
        {
            return null;
        }

        if (certificate is null || (errors & SslPolicyErrors.RemoteCertificateNotAvailable) != 0)
        {
            return "the broker sent no certificate";
        }

        if ((errors & SslPolicyErrors.RemoteCertificateNameMismatch) != 0)
        {
            return $"the broker's certificate ({certificate.Subject}) is not for the name the worker connects to (set {tlsKey}:ServerName if the broker is reached under another name)";
        }

        if (authorities is null)
        {
            return errors == SslPolicyErrors.None
                ? null
                : $"the broker's certificate ({certificate.Subject}, issued by {certificate.Issuer}) is not trusted by this machine's root certificates ({Statuses(chain)}); for a private CA set {tlsKey}:CaFile";
        }

        using var custom = new X509Chain();
        custom.ChainPolicy.TrustMode = X509ChainTrustMode.CustomRootTrust;
        custom.ChainPolicy.CustomTrustStore.AddRange(authorities);
        // A private CA seldom publishes revocation lists; trust in it is the configured file.
        custom.ChainPolicy.RevocationMode = X509RevocationMode.NoCheck;
        if (chain is not null)
        {
            foreach (X509ChainElement element in chain.ChainElements)
            {
                custom.ChainPolicy.ExtraStore.Add(element.Certificate);
            }
        }

        using var leaf = new X509Certificate2(certificate);
        return custom.Build(leaf)
            ? null
            : $"the broker's certificate ({certificate.Subject}, issued by {certificate.Issuer}) does not chain to a CA in {tlsKey}:CaFile ({Statuses(custom)})";
    }

    private static string Statuses(X509Chain? chain)
    {
        string[] statuses = chain?.ChainStatus.Select(s => s.Status.ToString()).Distinct().ToArray() ?? [];
        return statuses.Length == 0 ? "no chain" : string.Join(", ", statuses);
    }
}
