using System.Net;
using System.Security.Cryptography;
using System.Security.Cryptography.X509Certificates;

namespace OmronHostLink.Testing;

/// <summary>
/// A private CA and a broker certificate it signed (for 127.0.0.1 and localhost), made in memory with
/// <see cref="CertificateRequest"/> and written as PEM files for Mosquitto's cafile/certfile/keyfile.
/// </summary>
public sealed class TestCertificates : IDisposable
{
    private TestCertificates(X509Certificate2 authority, X509Certificate2 server, string serverKeyPem)
    {
        Authority = authority;
        Server = server;
        ServerKeyPem = serverKeyPem;
    }

    /// <summary>The CA certificate (with its key).</summary>
    public X509Certificate2 Authority { get; }

    /// <summary>The broker's certificate.</summary>
    public X509Certificate2 Server { get; }

    /// <summary>The broker's private key, PKCS#8 PEM.</summary>
    public string ServerKeyPem { get; }

    /// <summary>Makes a CA named <paramref name="authorityName"/> and a server certificate for 127.0.0.1/localhost signed by it.</summary>
    public static TestCertificates Create(string authorityName = "OmronHostLink test CA")
    {
        DateTimeOffset now = DateTimeOffset.UtcNow;
        using ECDsa caKey = ECDsa.Create(ECCurve.NamedCurves.nistP256);
        var caRequest = new CertificateRequest($"CN={authorityName}", caKey, HashAlgorithmName.SHA256);
        caRequest.CertificateExtensions.Add(new X509BasicConstraintsExtension(certificateAuthority: true, hasPathLengthConstraint: true, pathLengthConstraint: 0, critical: true));
        caRequest.CertificateExtensions.Add(new X509KeyUsageExtension(X509KeyUsageFlags.KeyCertSign | X509KeyUsageFlags.CrlSign, critical: true));
        caRequest.CertificateExtensions.Add(new X509SubjectKeyIdentifierExtension(caRequest.PublicKey, critical: false));
        X509Certificate2 authority = caRequest.CreateSelfSigned(now.AddDays(-1), now.AddDays(30));

        using ECDsa serverKey = ECDsa.Create(ECCurve.NamedCurves.nistP256);
        var request = new CertificateRequest("CN=127.0.0.1", serverKey, HashAlgorithmName.SHA256);
        request.CertificateExtensions.Add(new X509BasicConstraintsExtension(false, false, 0, critical: true));
        request.CertificateExtensions.Add(new X509KeyUsageExtension(X509KeyUsageFlags.DigitalSignature, critical: true));
        request.CertificateExtensions.Add(new X509EnhancedKeyUsageExtension([new Oid("1.3.6.1.5.5.7.3.1", "Server Authentication")], critical: false));
        var names = new SubjectAlternativeNameBuilder();
        names.AddIpAddress(IPAddress.Loopback);
        names.AddDnsName("localhost");
        request.CertificateExtensions.Add(names.Build());
        request.CertificateExtensions.Add(X509AuthorityKeyIdentifierExtension.CreateFromCertificate(authority, includeKeyIdentifier: true, includeIssuerAndSerial: false));
        byte[] serial = RandomNumberGenerator.GetBytes(16);
        serial[0] &= 0x7F;
        X509Certificate2 server = request.Create(authority, now.AddDays(-1), now.AddDays(29), serial);
        return new TestCertificates(authority, server, serverKey.ExportPkcs8PrivateKeyPem());
    }

    /// <summary>Writes the CA certificate as PEM to <paramref name="path"/> (what the worker's <c>Mqtt:Tls:CaFile</c> names).</summary>
    public string WriteAuthority(string path)
    {
        File.WriteAllText(path, Authority.ExportCertificatePem());
        return path;
    }

    /// <summary>Writes ca.pem, server.pem and server.key into <paramref name="directory"/> for the broker.</summary>
    public void WriteBrokerFiles(string directory)
    {
        WriteAuthority(Path.Combine(directory, "ca.pem"));
        File.WriteAllText(Path.Combine(directory, "server.pem"), Server.ExportCertificatePem());
        File.WriteAllText(Path.Combine(directory, "server.key"), ServerKeyPem);
    }

    /// <summary>A client certificate for <paramref name="name"/> signed by this CA, with its key, in memory (for a test's own MQTT client).</summary>
    public X509Certificate2 CreateClient(string name)
    {
        string directory = Directory.CreateTempSubdirectory("ohl-client-").FullName;
        try
        {
            (string certificate, string? key) = WriteClient(directory, name);
            return X509Certificate2.CreateFromPemFile(certificate, key);
        }
        finally
        {
            Directory.Delete(directory, recursive: true);
        }
    }

    /// <summary>
    /// Makes a client certificate for <paramref name="name"/> signed by this CA (extended key usage: client
    /// authentication), valid from <paramref name="notBefore"/> to <paramref name="notAfter"/> (by default from an hour
    /// ago for 20 days; both must lie within the CA's own validity, which starts a day ago), and writes it into
    /// <paramref name="directory"/>: a PEM certificate and its PKCS#8 PEM key, or with <paramref name="pkcs12Password"/>
    /// a PKCS#12 file holding both.
    /// </summary>
    /// <returns>The certificate's file and its key's (null for PKCS#12).</returns>
    public (string Certificate, string? Key) WriteClient(string directory, string name, DateTimeOffset? notBefore = null, DateTimeOffset? notAfter = null, string? pkcs12Password = null)
    {
        DateTimeOffset now = DateTimeOffset.UtcNow;
        using RSA key = RSA.Create(2048);
        var request = new CertificateRequest($"CN={name}", key, HashAlgorithmName.SHA256, RSASignaturePadding.Pkcs1);
        request.CertificateExtensions.Add(new X509BasicConstraintsExtension(false, false, 0, critical: true));
        request.CertificateExtensions.Add(new X509KeyUsageExtension(X509KeyUsageFlags.DigitalSignature | X509KeyUsageFlags.KeyEncipherment, critical: true));
        request.CertificateExtensions.Add(new X509EnhancedKeyUsageExtension([new Oid("1.3.6.1.5.5.7.3.2", "Client Authentication")], critical: false));
        request.CertificateExtensions.Add(X509AuthorityKeyIdentifierExtension.CreateFromCertificate(Authority, includeKeyIdentifier: true, includeIssuerAndSerial: false));
        byte[] serial = RandomNumberGenerator.GetBytes(16);
        serial[0] &= 0x7F;
        // An RSA key signed by the ECDSA CA (the request's own algorithm differs from the issuer's).
        using ECDsa issuerKey = Authority.GetECDsaPrivateKey()!;
        using X509Certificate2 certificate = request.Create(Authority.SubjectName, X509SignatureGenerator.CreateForECDsa(issuerKey), notBefore ?? now.AddHours(-1), notAfter ?? now.AddDays(20), serial);
        if (pkcs12Password is not null)
        {
            using X509Certificate2 withKey = certificate.CopyWithPrivateKey(key);
            string pfx = Path.Combine(directory, name + ".p12");
            File.WriteAllBytes(pfx, withKey.Export(X509ContentType.Pkcs12, pkcs12Password));
            return (pfx, null);
        }

        string pem = Path.Combine(directory, name + ".pem");
        string keyFile = Path.Combine(directory, name + ".key");
        File.WriteAllText(pem, certificate.ExportCertificatePem());
        File.WriteAllText(keyFile, key.ExportPkcs8PrivateKeyPem());
        return (pem, keyFile);
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Authority.Dispose();
        Server.Dispose();
    }
}
