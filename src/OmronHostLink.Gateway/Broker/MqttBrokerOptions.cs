using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// The broker connection of a section that publishes over MQTT (<c>Mqtt</c>, <c>Sparkplug</c>): the same keys, defaults
/// and rules (<see cref="MqttBrokerOptionsValidator"/>) in each.
/// </summary>
internal abstract class MqttBrokerOptions
{
    /// <summary>The broker's host name or address. Required.</summary>
    public string Host { get; set; } = "";

    /// <summary>The broker's port. Default 1883, or 8883 with TLS.</summary>
    public int? Port { get; set; }

    /// <summary>The MQTT client id, unique on the broker. Default: see <see cref="ClientIdOrDefault"/>.</summary>
    public string? ClientId { get; set; }

    /// <summary>User name for the broker; none by default.</summary>
    public string? Username { get; set; }

    /// <summary>
    /// Password for the broker (needs <see cref="Username"/>). Keep it out of appsettings.json: set it in the
    /// environment (<c>Mqtt__Password</c>, <c>Sparkplug__Password</c>) or a secret store.
    /// </summary>
    public string? Password { get; set; }

    /// <summary>TLS to the broker.</summary>
    public MqttTlsOptions Tls { get; set; } = new();

    /// <summary>
    /// MQTT keep-alive: how soon a silent connection is noticed. Default 15 s; whole seconds from 1 s to 18:12:15 (0
    /// would turn keep-alive off).
    /// </summary>
    public TimeSpan KeepAlive { get; set; } = TimeSpan.FromSeconds(15);

    /// <summary>How long the broker may take to accept the connection, a subscription or a message. Default 10 s.</summary>
    public TimeSpan Timeout { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>Delay between connection attempts: Initial, doubling up to Max. Default 1 s to 30 s.</summary>
    public BackoffOptions Reconnect { get; set; } = new();

    /// <summary>The port in effect.</summary>
    public int PortOrDefault => Port ?? (Tls.Enabled ? 8883 : 1883);

    /// <summary>The client id in effect: <see cref="ClientId"/>, or the section's default when it is not set.</summary>
    public abstract string ClientIdOrDefault { get; }
}
