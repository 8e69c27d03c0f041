namespace OmronHostLink.DependencyInjection;

/// <summary>
/// A serial-device server (or the simulator) that carries the Host Link line over TCP. In configuration either a
/// section (<c>"Tcp": { "Host": "192.0.2.10", "Port": 4001 }</c>) or the short form <c>"Tcp": "192.0.2.10:4001"</c>.
/// </summary>
public sealed class HostLinkTcpSettings
{
    /// <summary>The server's host name or address.</summary>
    public string? Host { get; set; }

    /// <summary>The server's TCP port, 1-65535. Required with <see cref="Host"/>.</summary>
    public int? Port { get; set; }

    /// <summary>How long a connection attempt may take; more than zero, at most 5 minutes. Default 5 s.</summary>
    public TimeSpan? ConnectTimeout { get; set; }
}
