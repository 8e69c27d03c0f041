using System.Globalization;
using System.Net;
using System.Net.Sockets;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Status;
using OmronHostLink.Gateway.Tests.Mqtt;

namespace OmronHostLink.Gateway.Tests.Status;

/// <summary>
/// A gateway polling a recording simulator (link <c>plc</c>) with its status page on a free loopback port, built from
/// in-memory configuration as the program builds it.
/// </summary>
internal sealed class StatusGateway : IAsyncDisposable
{
    private StatusGateway(RecordingSimulator simulator, IHost host, CapturingLoggerProvider logs, Dictionary<string, string?> config)
    {
        Simulator = simulator;
        Host = host;
        Logs = logs;
        Config = config;
    }

    /// <summary>The PLC side.</summary>
    public RecordingSimulator Simulator { get; }

    /// <summary>The gateway.</summary>
    public IHost Host { get; }

    /// <summary>Its log.</summary>
    public CapturingLoggerProvider Logs { get; }

    /// <summary>Its configuration.</summary>
    public Dictionary<string, string?> Config { get; }

    /// <summary>The status page's server.</summary>
    public StatusServer Server => Host.Services.GetRequiredService<StatusServer>();

    /// <summary>The page's address: <c>http://127.0.0.1:port/</c>.</summary>
    public Uri Address => new($"http://127.0.0.1:{Server.EndPoint!.Port}/");

    /// <summary>
    /// The configuration of a gateway polling <paramref name="simulator"/> (fast timings, no MQTT) with its status page
    /// on a free port of 127.0.0.1, refreshed every 250 ms.
    /// </summary>
    public static Dictionary<string, string?> Configuration(RecordingSimulator simulator)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["Status:Port"] = FreePort().ToString(CultureInfo.InvariantCulture);
        config["Status:RefreshInterval"] = "250ms";
        return config;
    }

    /// <summary>Starts the gateway over <paramref name="config"/> (see <see cref="Configuration"/>) and waits until its page listens.</summary>
    public static async Task<StatusGateway> StartAsync(RecordingSimulator simulator, Dictionary<string, string?> config)
    {
        var logs = new CapturingLoggerProvider();
        IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        var gateway = new StatusGateway(simulator, host, logs, config);
        await MqttGatewayConfig.Eventually(() => gateway.Server.EndPoint is not null, "the status page listens", logs);
        return gateway;
    }

    /// <summary>A port of 127.0.0.1 free a moment ago.</summary>
    public static int FreePort()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        return ((IPEndPoint)listener.LocalEndpoint).Port;
    }

    /// <summary>An HTTP client for the page.</summary>
    public HttpClient Client(bool allowRedirect = true)
        => new(new SocketsHttpHandler { AllowAutoRedirect = allowRedirect, UseCookies = false }) { BaseAddress = Address, Timeout = TimeSpan.FromMinutes(1) };

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        await Host.StopAsync();
        Host.Dispose();
    }
}
