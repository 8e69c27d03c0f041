using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Mqtt;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The <c>Sparkplug</c> section: publish the tags as a Sparkplug B edge node (for Ignition's MQTT Engine and other
/// Sparkplug host applications), beside or instead of the JSON output. Its own MQTT connection, because the edge
/// node's death certificate (NDEATH) is that connection's will. Without the section (or with <c>Enabled: false</c>)
/// nothing is published.
/// </summary>
public sealed class SparkplugOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "Sparkplug";

    /// <summary>False to keep the section in the file without connecting. Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>The Sparkplug group the edge node belongs to (the second topic level). Required.</summary>
    public string GroupId { get; set; } = "";

    /// <summary>The edge node's id (the fourth topic level): this gateway. Required.</summary>
    public string EdgeNodeId { get; set; } = "";

    /// <summary>The broker's host name or address. Required.</summary>
    public string Host { get; set; } = "";

    /// <summary>The broker's port. Default 1883, or 8883 with TLS.</summary>
    public int? Port { get; set; }

    /// <summary>The MQTT client id. Default <c>{GroupId}-{EdgeNodeId}</c>.</summary>
    public string? ClientId { get; set; }

    /// <summary>User name for the broker; none by default.</summary>
    public string? Username { get; set; }

    /// <summary>Password for the broker (needs <see cref="Username"/>); set it in the environment (<c>Sparkplug__Password</c>).</summary>
    public string? Password { get; set; }

    /// <summary>TLS to the broker, as for the <c>Mqtt</c> section.</summary>
    public MqttTlsOptions Tls { get; set; } = new();

    /// <summary>MQTT keep-alive. Default 15 s; whole seconds.</summary>
    public TimeSpan KeepAlive { get; set; } = TimeSpan.FromSeconds(15);

    /// <summary>How long the broker may take to accept the connection or a subscription. Default 10 s.</summary>
    public TimeSpan Timeout { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>Delay between connection attempts: Initial, doubling up to Max. Default 1 s to 30 s.</summary>
    public BackoffOptions Reconnect { get; set; } = new();

    /// <summary>Device commands (DCMD) that write tags.</summary>
    public SparkplugWriteOptions Writes { get; set; } = new();

    /// <summary>The port in effect.</summary>
    public int PortOrDefault => Port ?? (Tls.Enabled ? 8883 : 1883);

    /// <summary>The client id in effect.</summary>
    public string ClientIdOrDefault => string.IsNullOrWhiteSpace(ClientId) ? $"{GroupId}-{EdgeNodeId}" : ClientId;
}

/// <summary>The <c>Sparkplug:Writes</c> section.</summary>
public sealed class SparkplugWriteOptions
{
    /// <summary>
    /// Carry out DCMD metric writes to the tags configured <c>Writable</c> (the same allowlist and value checks as MQTT
    /// JSON writes). Default false: every DCMD is refused and logged, and nothing reaches a PLC.
    /// </summary>
    public bool Enabled { get; set; }
}
