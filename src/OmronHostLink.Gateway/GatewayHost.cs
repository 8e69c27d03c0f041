using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.DependencyInjection.Extensions;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Simulation;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Statistics;
using OmronHostLink.Gateway.Telemetry;

namespace OmronHostLink.Gateway;

/// <summary>Builds the worker's generic host: options, validation, a client per link, the optional simulator and the link pollers.</summary>
public static class GatewayHost
{
    /// <summary>A builder with the usual defaults (appsettings.json, appsettings.{Environment}.json, environment variables, command line, console logging).</summary>
    public static HostApplicationBuilder CreateBuilder(string[] args)
        => Configure(Host.CreateApplicationBuilder(args));

    /// <summary>
    /// A builder from explicit settings: tests pass <c>DisableDefaults = true</c> and their own
    /// <see cref="HostApplicationBuilderSettings.Configuration"/>, and add a logger provider to the result.
    /// </summary>
    public static HostApplicationBuilder CreateBuilder(HostApplicationBuilderSettings settings)
        => Configure(Host.CreateApplicationBuilder(settings));

    /// <summary>The generic host's own log category, where a failed start is logged with its stack trace.</summary>
    private const string HostCategory = "Microsoft.Extensions.Hosting.Internal.Host";

    /// <summary>The sections the gateway reads, besides the generic host's own.</summary>
    internal static readonly string[] Sections =
    [
        GatewayOptions.SectionName, SimulatorOptions.SectionName, MqttOptions.SectionName, SparkplugOptions.SectionName, TelemetryOptions.SectionName, "Logging",
    ];

    private static HostApplicationBuilder Configure(HostApplicationBuilder builder)
    {
        IServiceCollection services = builder.Services;
        services.TryAddSingleton(TimeProvider.System);

        // Read once: every check sees the links and groups the gateway polls, and each section is judged once.
        var gateway = new GatewayConfiguration(builder.Configuration);
        services.AddSingleton(gateway);
        new GatewayOptionsValidator(gateway).AddTo(services, options => options.Links = gateway.HostLink.Links);
        new SimulatorOptionsValidator(gateway).AddTo(services);

        // Order matters: hosted services start in registration order and stop in reverse, so the simulator listens
        // before the links connect and outlives them, and the MQTT output sends the links' last states.
        services.AddSingleton<SimulatorHostedService>();
        services.AddHostedService(sp => sp.GetRequiredService<SimulatorHostedService>());
        // The outputs (each an ITagOutput; the polling reports to all of them in registration order).
        services.AddLinkStatistics();
        services.AddMqttOutput(gateway, builder.Environment.ContentRootPath);
        services.AddSparkplugOutput(gateway);
        services.AddSingleton<PollingHostedService>();
        services.AddHostedService(sp => sp.GetRequiredService<PollingHostedService>());
        services.AddTelemetryExport(gateway);

        // Once every output has added its rules to the HostLink section's check.
        if (StartupCheck.Passes(gateway))
        {
            services.AddLinkClients(gateway);
        }
        else
        {
            // The start is going to fail validation, and Program prints every failure, each naming its key. The host
            // would first log "Hosting failed to start" with the framework's stack trace: that is all noise here.
            builder.Logging.AddFilter(HostCategory, LogLevel.None);
        }

        // Each is a no-op unless its service manager started the process. Windows: reports SERVICE_RUNNING/STOPPED to
        // the service control manager, turns a service stop into a graceful shutdown and logs to the event log.
        // systemd: sd_notify READY=1 once every hosted service has started and STOPPING=1 on SIGTERM (Type=notify),
        // and journald-style console logs.
        services.AddWindowsService(o => o.ServiceName = GatewayNames.Service);
        services.AddSystemd();
        return builder;
    }
}
