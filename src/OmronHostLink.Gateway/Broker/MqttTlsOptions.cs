namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// The <c>Tls</c> section of a broker connection (<c>Mqtt:Tls</c>, <c>Sparkplug:Tls</c>, or a server's own
/// <c>Servers:N:Tls</c>): how the broker is trusted and, optionally, the certificate the gateway proves itself with.
/// </summary>
internal sealed class MqttTlsOptions
{
    /// <summary>Connect with TLS. Default false.</summary>
    public bool Enabled { get; set; }

    /// <summary>
    /// A PEM file with the CA certificate(s) that signed the broker's certificate (a private CA). When set, only these
    /// CAs are trusted for the broker, as <c>mosquitto_sub --cafile</c> does; otherwise the system's trusted roots are.
    /// </summary>
    public string? CaFile { get; set; }

    /// <summary>The name the broker's certificate must carry. Default <see cref="MqttBrokerOptions.Host"/>.</summary>
    public string? ServerName { get; set; }

    /// <summary>
    /// Accept any server certificate (no validation at all). For a laboratory only: anyone on the path can read and
    /// change the data. Logged as a warning at start. Default false.
    /// </summary>
    public bool AllowUntrustedCertificates { get; set; }

    /// <summary>
    /// The gateway's client certificate, for a broker that authenticates clients by certificate: a PEM certificate
    /// (with its key in <see cref="ClientKeyFile"/>) or a PKCS#12 file (<c>.pfx</c>, <c>.p12</c>) holding both. None by
    /// default. Checked at start: it must exist, match its key, and be valid now.
    /// </summary>
    public string? ClientCertificateFile { get; set; }

    /// <summary>The PEM private key of a PEM <see cref="ClientCertificateFile"/> (PKCS#8, PKCS#1 or SEC1, encrypted or not).</summary>
    public string? ClientKeyFile { get; set; }

    /// <summary>
    /// The password of an encrypted <see cref="ClientKeyFile"/> or of a PKCS#12 <see cref="ClientCertificateFile"/>. Keep
    /// it in the environment (<c>Mqtt__Tls__ClientKeyPassword</c>), not in the file.
    /// </summary>
    public string? ClientKeyPassword { get; set; }
}
