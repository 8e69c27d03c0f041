using System.Globalization;
using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// The gateway's TLS client certificate (<see cref="MqttTlsOptions.ClientCertificateFile"/>): read from a PEM certificate
/// and its PEM key, or from a PKCS#12 file, and checked — it exists, its key is there and matches, it is valid now and,
/// when it says what it is for, it is for client authentication. Every problem names its key.
/// </summary>
internal static class ClientCertificate
{
    private const string ClientAuthentication = "1.3.6.1.5.5.7.3.2";

    /// <summary>Reads and checks the client certificate of <paramref name="tls"/>.</summary>
    /// <param name="tls">The TLS settings, with <see cref="MqttTlsOptions.ClientCertificateFile"/> set.</param>
    /// <param name="tlsKey">Their key (<c>Mqtt:Tls</c>), which every problem names.</param>
    /// <param name="now">The time it must be valid at.</param>
    /// <returns>The certificate with its private key.</returns>
    /// <exception cref="InvalidOperationException">It cannot be used; the message says why, naming the key.</exception>
    public static X509Certificate2 Load(MqttTlsOptions tls, string tlsKey, DateTimeOffset now)
    {
        ArgumentNullException.ThrowIfNull(tls);
        string certificateKey = tlsKey + ":ClientCertificateFile";
        string path = tls.ClientCertificateFile ?? throw new InvalidOperationException($"{certificateKey} is not set.");
        byte[] content = Read(path, certificateKey);
        X509Certificate2 certificate = IsPem(content)
            ? FromPem(tls, tlsKey, path, content)
            : X509Certificate2.GetCertContentType(content) == X509ContentType.Pkcs12
                ? FromPkcs12(tls, tlsKey, path, content)
                : throw new InvalidOperationException($"{certificateKey} '{path}' is neither a PEM certificate (-----BEGIN CERTIFICATE-----) nor a PKCS#12 file (.pfx, .p12).");
        try
        {
            Check(certificate, certificateKey, path, now);
            return OperatingSystem.IsWindows() ? Persisted(certificate) : certificate;
        }
        catch
        {
            certificate.Dispose();
            throw;
        }
    }

    /// <summary>Why the client certificate of <paramref name="tls"/> cannot be used, naming its key; null when it can.</summary>
    public static string? Problem(MqttTlsOptions tls, string tlsKey, DateTimeOffset now)
    {
        try
        {
            using X509Certificate2 certificate = Load(tls, tlsKey, now);
            return null;
        }
        catch (InvalidOperationException e)
        {
            return e.Message;
        }
    }

    /// <summary>The certificate as a log names it: its subject and issuer.</summary>
    public static string Describe(X509Certificate2 certificate)
    {
        ArgumentNullException.ThrowIfNull(certificate);
        return $"{certificate.Subject}, issued by {certificate.Issuer}";
    }

    private static byte[] Read(string path, string key)
    {
        if (!File.Exists(path))
        {
            throw new InvalidOperationException($"{key} '{path}' does not exist (relative paths start at the working directory, {Environment.CurrentDirectory}).");
        }

        try
        {
            return File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new InvalidOperationException($"{key} '{path}' cannot be read: {e.Message}", e);
        }
    }

    private static bool IsPem(byte[] content)
        => content.AsSpan().IndexOf("-----BEGIN "u8) >= 0;

    private static X509Certificate2 FromPkcs12(MqttTlsOptions tls, string tlsKey, string path, byte[] content)
    {
        if (!string.IsNullOrEmpty(tls.ClientKeyFile))
        {
            throw new InvalidOperationException($"{tlsKey}:ClientKeyFile is set, but {tlsKey}:ClientCertificateFile '{path}' is a PKCS#12 file, which holds its key: leave ClientKeyFile unset.");
        }

        try
        {
            return X509CertificateLoader.LoadPkcs12(content, tls.ClientKeyPassword, X509KeyStorageFlags.DefaultKeySet);
        }
        catch (CryptographicException e)
        {
            string password = string.IsNullOrEmpty(tls.ClientKeyPassword) ? "without a password (set " + tlsKey + ":ClientKeyPassword)" : "with " + tlsKey + ":ClientKeyPassword";
            throw new InvalidOperationException($"{tlsKey}:ClientCertificateFile '{path}' cannot be opened {password}: {e.Message.TrimEnd('.')}.", e);
        }
    }

    private static X509Certificate2 FromPem(MqttTlsOptions tls, string tlsKey, string path, byte[] content)
    {
        string certificateKey = tlsKey + ":ClientCertificateFile";
        X509Certificate2 certificate;
        try
        {
            certificate = X509Certificate2.CreateFromPem(System.Text.Encoding.ASCII.GetString(content));
        }
        catch (CryptographicException e)
        {
            throw new InvalidOperationException($"{certificateKey} '{path}' holds no readable PEM certificate: {e.Message.TrimEnd('.')}.", e);
        }

        using (certificate)
        {
            if (string.IsNullOrEmpty(tls.ClientKeyFile))
            {
                throw new InvalidOperationException($"{certificateKey} '{path}' is a PEM certificate: set {tlsKey}:ClientKeyFile to its private key (or give a PKCS#12 file that holds both).");
            }

            string keyKey = tlsKey + ":ClientKeyFile";
            string keyText = System.Text.Encoding.ASCII.GetString(Read(tls.ClientKeyFile, keyKey));
            using AsymmetricAlgorithm key = certificate.GetRSAPublicKey() is not null ? RSA.Create()
                : certificate.GetECDsaPublicKey() is not null ? ECDsa.Create()
                : throw new InvalidOperationException($"{certificateKey} '{path}': its key is neither RSA nor ECDSA, which the gateway can use.");
            try
            {
                if (keyText.Contains("ENCRYPTED PRIVATE KEY", StringComparison.Ordinal))
                {
                    if (string.IsNullOrEmpty(tls.ClientKeyPassword))
                    {
                        throw new InvalidOperationException($"{keyKey} '{tls.ClientKeyFile}' is encrypted: set {tlsKey}:ClientKeyPassword.");
                    }

                    key.ImportFromEncryptedPem(keyText, tls.ClientKeyPassword);
                }
                else
                {
                    key.ImportFromPem(keyText);
                }
            }
            catch (Exception e) when (e is ArgumentException or CryptographicException)
            {
                throw new InvalidOperationException($"{keyKey} '{tls.ClientKeyFile}' holds no {(key is RSA ? "RSA" : "ECDSA")} private key the gateway can read{(string.IsNullOrEmpty(tls.ClientKeyPassword) ? "" : " with " + tlsKey + ":ClientKeyPassword")}: {e.Message.TrimEnd('.')}.", e);
            }

            try
            {
                return key is RSA rsa ? certificate.CopyWithPrivateKey(rsa) : certificate.CopyWithPrivateKey((ECDsa)key);
            }
            catch (Exception e) when (e is ArgumentException or CryptographicException)
            {
                throw new InvalidOperationException($"{keyKey} '{tls.ClientKeyFile}' is not the key of {certificateKey} '{path}' ({certificate.Subject}): {e.Message.TrimEnd('.')}.", e);
            }
        }
    }

    private static void Check(X509Certificate2 certificate, string key, string path, DateTimeOffset now)
    {
        if (!certificate.HasPrivateKey)
        {
            throw new InvalidOperationException($"{key} '{path}' holds the certificate {certificate.Subject} without its private key.");
        }

        string format(DateTime t) => t.ToUniversalTime().ToString("yyyy-MM-dd HH:mm:ss 'UTC'", CultureInfo.InvariantCulture);
        if (now.UtcDateTime > certificate.NotAfter.ToUniversalTime())
        {
            throw new InvalidOperationException($"{key} '{path}': the certificate {certificate.Subject} expired on {format(certificate.NotAfter)}; a broker that checks client certificates refuses it. Renew it.");
        }

        if (now.UtcDateTime < certificate.NotBefore.ToUniversalTime())
        {
            throw new InvalidOperationException($"{key} '{path}': the certificate {certificate.Subject} is not valid before {format(certificate.NotBefore)} (is this machine's clock right?).");
        }

        foreach (X509EnhancedKeyUsageExtension usage in certificate.Extensions.OfType<X509EnhancedKeyUsageExtension>())
        {
            var purposes = usage.EnhancedKeyUsages.Cast<Oid>().ToList();
            if (!purposes.Any(p => p.Value == ClientAuthentication))
            {
                throw new InvalidOperationException($"{key} '{path}': the certificate {certificate.Subject} is not for client authentication (its extended key usage allows {string.Join(", ", purposes.Select(p => p.FriendlyName ?? p.Value))}).");
            }
        }
    }

    /// <summary>On Windows, TLS (SChannel) cannot use a key that lives only in memory: the certificate goes through PKCS#12 once.</summary>
    private static X509Certificate2 Persisted(X509Certificate2 certificate)
    {
        using (certificate)
        {
            return X509CertificateLoader.LoadPkcs12(certificate.Export(X509ContentType.Pkcs12), null, X509KeyStorageFlags.DefaultKeySet);
        }
    }
}
