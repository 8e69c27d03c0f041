using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.DependencyInjection;
using OmronHostLink.Transports;

namespace OmronHostLink.Worker.Configuration;

/// <summary>
/// One <see cref="HostLinkClient"/> per enabled link, registered through OmronHostLink.DependencyInjection as a keyed
/// singleton named after the link, its settings mapped from the link's own keys (<c>Serial</c>, <c>Tcp</c>,
/// <c>ConnectTimeout</c>, <c>LineBaudRate</c>, <c>Protocol</c>, <c>TurnaroundAllowance</c>, <c>ReadRetries</c>,
/// <c>WordOrder</c>), so the worker's configuration keeps its form.
/// </summary>
public static class LinkClients
{
    /// <summary>
    /// Registers the clients of the enabled links in <paramref name="configuration"/>'s <c>HostLink</c> section. An
    /// invalid section registers none: the host then fails at start with the worker's own messages, which name the
    /// link's keys, and with nothing else.
    /// </summary>
    public static IServiceCollection AddLinkClients(this IServiceCollection services, IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        WorkerOptions? options;
        try
        {
            options = configuration.GetSection(WorkerOptions.SectionName).Get<WorkerOptions>();
        }
        catch (InvalidOperationException)
        {
            return services; // A value the binder cannot convert: start-up reports it.
        }

        if (options is null || new WorkerOptionsValidator().Validate(null, options).Failed)
        {
            return services;
        }

        foreach ((string name, LinkOptions link) in options.Links)
        {
            if (link.Enabled)
            {
                services.AddHostLinkClient(name, settings => Map(link, settings));
            }
        }

        return services;
    }

    /// <summary>Copies a link's settings into the client settings of the DI package.</summary>
    public static void Map(LinkOptions link, HostLinkClientSettings settings)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(settings);
        settings.Protocol = link.Protocol;
        settings.TurnaroundAllowance = link.TurnaroundAllowance;
        settings.ReadRetries = link.ReadRetries;
        settings.WordOrder = link.WordOrder;
        if (link.Serial is { } serial)
        {
            HostLinkSerialSettings s = settings.Serial;
            s.PortName = serial.PortName;
            s.BaudRate = serial.BaudRate;
            s.DataBits = serial.DataBits;
            s.Parity = serial.Parity;
            s.StopBits = serial.StopBits;
            s.Handshake = serial.Handshake;
            s.DtrEnable = serial.DtrEnable;
            s.RtsEnable = serial.RtsEnable;
            return;
        }

        (settings.Tcp.Host, int port) = TcpTransport.ParseEndpoint(link.Tcp!);
        settings.Tcp.Port = port;
        settings.Tcp.ConnectTimeout = link.ConnectTimeout;

        // The line behind the serial-device server: its speed sets the frame deadlines (Omron's 7E2 format).
        settings.Serial.BaudRate = link.LineBaudRate;
    }
}
