using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// A serial-device server (or the simulator) that carries the Host Link line over TCP. In configuration either a
/// section (<c>"Tcp": { "Host": "192.0.2.10", "Port": 4001 }</c>) or the short form <c>"Tcp": "192.0.2.10:4001"</c>.
/// The serial line behind it is described by <see cref="HostLinkClientSettings.Serial"/>.
/// </summary>
public sealed class HostLinkTcpSettings : HostLinkEndpointSettings
{
    private static readonly SettingKeys<HostLinkTcpSettings> Keys = new("a TCP setting")
    {
        { nameof(Host), (v, t) => t.Host = v.Text() ?? t.Host },
        { nameof(Port), (v, t) => t.Port = v.Integer() ?? t.Port },
        { nameof(ConnectTimeout), (v, t) => t.ConnectTimeout = v.Duration() ?? t.ConnectTimeout },
    };

    /// <summary>The server's host name or address.</summary>
    public string? Host { get; set; }

    /// <summary>The server's TCP port, 1-65535. Required with <see cref="Host"/>.</summary>
    public int? Port { get; set; }

    /// <summary>How long a connection attempt may take; more than zero, at most 5 minutes. Default 5 s.</summary>
    public TimeSpan? ConnectTimeout { get; set; }

    internal override string Key => "Tcp";

    internal override string ChoiceKey => "Tcp";

    internal override string What => "a serial-device server";

    internal override string Hint => "Tcp (host:port of a serial-device server)";

    internal override IEnumerable<string> KeyNames => Keys;

    internal override bool IsChosen => Host is not null || Port is not null;

    internal override void Read(SettingValue value)
    {
        // Configuration can hold both a value and keys below it (Tcp=host:port and Tcp:ConnectTimeout=2s, as
        // environment variables or command-line arguments write them): the short form is read beside the section.
        string? text = value.IsSection ? value.WrittenValue : value.Text();
        if (value.IsSection)
        {
            value.Section(Keys, this);
        }

        if (!string.IsNullOrWhiteSpace(text))
        {
            if (SettingRules.TryParseEndpoint(text!, out string host, out int port, out string? error))
            {
                (Host, Port) = (host, port);
            }
            else
            {
                value.Problem(error!);
            }
        }
    }

    internal override void Check(HostLinkClientSettings client, List<HostLinkSettingsProblem> problems)
    {
        if (ConnectTimeout is { } timeout && SettingRules.ConnectTimeout(timeout) is { } slow)
        {
            problems.Add(new HostLinkSettingsProblem("Tcp:ConnectTimeout", slow));
        }

        if (!IsChosen || problems.Any(p => p.IsAtOrBelow("Tcp:Host") || p.IsAtOrBelow("Tcp:Port") || p.Key.Equals("Tcp", StringComparison.OrdinalIgnoreCase)))
        {
            return;
        }

        if (Host is null || SettingRules.Host(Host) is not null)
        {
            problems.Add(new HostLinkSettingsProblem("Tcp:Host", Host is null ? "is missing; write the serial-device server's host name or address" : SettingRules.Host(Host)!));
        }

        if (Port is not { } port)
        {
            problems.Add(new HostLinkSettingsProblem("Tcp:Port", $"is missing; write the serial-device server's TCP port (1-{SettingRules.MaxTcpPort})"));
        }
        else if (SettingRules.TcpPort(port) is { } bad)
        {
            problems.Add(new HostLinkSettingsProblem("Tcp:Port", bad));
        }
    }

    // The line's timing reaches the client through its options (HostLinkClientSettings.ToClientOptions).
    internal override IHostLinkTransport CreateTransport(HostLinkClientSettings client) => new TcpTransport(Host!, Port!.Value, ConnectTimeout);
}
