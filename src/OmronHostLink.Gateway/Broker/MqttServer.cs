using System.Globalization;

namespace OmronHostLink.Gateway.Broker;

/// <summary>
/// A broker a connection may use, as configured: the section's <c>Host</c>/<c>Port</c>/<c>Tls</c>, or one entry of its
/// <c>Servers</c> list (<see cref="MqttBrokerOptions.ServersInEffect"/>).
/// </summary>
/// <param name="Index">Its place in the list, from 0.</param>
/// <param name="Count">How many servers the list has (1 for the single-broker keys).</param>
/// <param name="Host">The host name or address.</param>
/// <param name="Port">The port in effect.</param>
/// <param name="Tls">The TLS settings in effect (its own, or the section's).</param>
/// <param name="Key">The configuration key it comes from: <c>Mqtt</c> or <c>Mqtt:Servers:1</c>.</param>
internal sealed record MqttServer(int Index, int Count, string Host, int Port, MqttTlsOptions Tls, string Key)
{
    /// <summary><c>host:port</c>.</summary>
    public string Address => $"{Host}:{Port.ToString(CultureInfo.InvariantCulture)}";

    /// <summary>How the logs name it: <c>host:port</c>, with its key when the list has several servers.</summary>
    public override string ToString() => Count == 1 ? Address : $"{Address} ({Key})";
}
