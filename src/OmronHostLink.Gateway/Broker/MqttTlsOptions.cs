namespace OmronHostLink.Gateway.Broker;

/// <summary>The <c>Tls</c> section of a broker connection (<c>Mqtt:Tls</c>, <c>Sparkplug:Tls</c>).</summary>
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
}
