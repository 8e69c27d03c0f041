namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// One broker of a section's server list (<c>Mqtt:Servers:0</c>, <c>Sparkplug:Servers:1</c>…): its address, its port and
/// its TLS. A server without a <c>Tls</c> section of its own takes the section's <c>Tls</c>.
/// </summary>
internal sealed class MqttServerOptions
{
    /// <summary>The broker's host name or address. Required.</summary>
    public string Host { get; set; } = "";

    /// <summary>The broker's port. Default 1883, or 8883 with TLS.</summary>
    public int? Port { get; set; }

    /// <summary>TLS to this broker; null to use the section's <c>Tls</c>.</summary>
    public MqttTlsOptions? Tls { get; set; }
}
