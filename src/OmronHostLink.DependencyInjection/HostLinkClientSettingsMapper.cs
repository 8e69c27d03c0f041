using System.Diagnostics.Metrics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using OmronHostLink.DependencyInjection.Configuration;
using OmronHostLink.Link;
using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection;

/// <summary>
/// Turns <see cref="HostLinkClientSettings"/> into the library's own types and a <see cref="HostLinkClient"/>. The one
/// place that knows the library's option types; settings left unset keep the library's defaults.
/// </summary>
internal static class HostLinkClientSettingsMapper
{
    /// <summary>
    /// Creates the client the settings describe, logging through the container's logger factory and measuring through
    /// its meter factory (when it has them), named in metrics and traces by its registered name.
    /// </summary>
    /// <param name="settings">Validated settings.</param>
    /// <param name="services">The container, for the logger and meter factories.</param>
    /// <param name="name">The client's registered name; null for the default client, named by its port or host:port.</param>
    public static HostLinkClient CreateClient(HostLinkClientSettings settings, IServiceProvider services, string? name)
    {
        HostLinkClientOptions options = ToClientOptions(settings);
        options.LoggerFactory = services.GetService<ILoggerFactory>();
        options.MeterFactory = services.GetService<IMeterFactory>();
        options.LinkName = name;
        SerialLineSettings line = ToSerialLineSettings(settings);
        if (settings.Serial.PortName is not null)
        {
            return HostLinkClient.ForSerialPort(line, options);
        }

        return HostLinkClient.ForTcp(settings.Tcp.Host!, settings.Tcp.Port!.Value, options, settings.Tcp.ConnectTimeout);
    }

    /// <summary>
    /// What the library's own checks refuse in these settings (none when the validator's rules are complete), without
    /// opening anything.
    /// </summary>
    public static IEnumerable<SettingsProblem> ProblemsTheLibraryFinds(HostLinkClientSettings settings)
    {
        var problems = new List<SettingsProblem>();
        try
        {
            ToClientOptions(settings).Validate();
            SerialLineSettings line = ToSerialLineSettings(settings);
            if (settings.Serial.PortName is not null)
            {
                line.Validate();
            }
            else
            {
                _ = new TcpTransport(settings.Tcp.Host!, settings.Tcp.Port!.Value, settings.Tcp.ConnectTimeout);
            }
        }
        catch (ArgumentException e)
        {
            problems.Add(new SettingsProblem("", e.Message));
        }

        return problems;
    }

    internal static HostLinkClientOptions ToClientOptions(HostLinkClientSettings s)
    {
        var options = new HostLinkClientOptions();
        options.UnitNumber = s.UnitNumber ?? options.UnitNumber;
        options.CommandSet = s.Protocol ?? options.CommandSet;
        options.TurnaroundAllowance = s.TurnaroundAllowance ?? options.TurnaroundAllowance;
        options.ReadRetries = s.ReadRetries ?? options.ReadRetries;
        options.WriteRetries = s.WriteRetries ?? options.WriteRetries;
        options.WordOrder = s.WordOrder ?? options.WordOrder;
        options.LocalEcho = s.LocalEcho ?? options.LocalEcho;
        options.FinsResponseWait = s.FinsResponseWait ?? options.FinsResponseWait;
        options.AllowReadModifyWriteBits = s.AllowReadModifyWriteBits ?? options.AllowReadModifyWriteBits;
        options.Model = s.Model ?? options.Model;

        // Over TCP the transport cannot know the line's speed: the deadlines come from these settings. A local port
        // gives its own timing from the same values.
        SerialLineSettings line = ToSerialLineSettings(s);
        options.LineTiming = new LineTiming(line.BaudRate, line.BitsPerCharacter);
        return options;
    }

    internal static SerialLineSettings ToSerialLineSettings(HostLinkClientSettings settings)
    {
        HostLinkSerialSettings s = settings.Serial;
        var line = new SerialLineSettings();
        line.PortName = s.PortName ?? line.PortName;
        line.BaudRate = s.BaudRate ?? line.BaudRate;
        line.DataBits = s.DataBits ?? line.DataBits;
        line.Parity = s.Parity ?? line.Parity;
        line.StopBits = s.StopBits ?? line.StopBits;
        line.Handshake = s.Handshake ?? line.Handshake;
        line.DtrEnable = s.DtrEnable ?? line.DtrEnable;
        line.RtsEnable = s.RtsEnable ?? line.RtsEnable;
        return line;
    }
}
