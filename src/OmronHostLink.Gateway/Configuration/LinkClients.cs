using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
using OmronHostLink.DependencyInjection;
using OmronHostLink.Transports;

namespace OmronHostLink.Gateway.Configuration;

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
        services.AddSingleton<IValidateOptions<GatewayOptions>, LineSpeedValidator>();
        if (!StartupCheck.Passes(configuration))
        {
            return services;
        }

        var options = new GatewayOptions();
        ConfigurationSchema.Bind(configuration.GetSection(GatewayOptions.SectionName), options);
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

    /// <summary>
    /// A serial-device server's line runs at a standard rate, as the client settings require: a <c>LineBaudRate</c> that
    /// is not one is reported by its own key rather than as the client's <c>Serial:BaudRate</c>.
    /// </summary>
    internal sealed class LineSpeedValidator : IValidateOptions<GatewayOptions>
    {
        private static readonly int[] StandardRates = [300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

        public ValidateOptionsResult Validate(string? name, GatewayOptions options)
        {
            string[] failures = options.Links
                .Where(l => l.Value is { Enabled: true, LineBaudRate: { } baud } && Array.IndexOf(StandardRates, baud) < 0)
                .Select(l => $"{GatewayOptions.SectionName}:Links:{l.Key}:LineBaudRate {l.Value.LineBaudRate} is not a standard rate ({string.Join(", ", StandardRates)}).")
                .ToArray();
            return failures.Length == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
        }
    }
}
