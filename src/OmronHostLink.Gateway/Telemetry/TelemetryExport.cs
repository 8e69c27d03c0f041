using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
using OpenTelemetry.Metrics;
using OpenTelemetry.Resources;
using OpenTelemetry.Trace;

namespace OmronHostLink.Gateway.Telemetry;

/// <summary>
/// Opt-in OpenTelemetry export of the library's and the worker's meters (and the library's traces): <c>Console</c>
/// prints them (to look at), <c>Otlp</c> sends them to a collector configured by the standard
/// <c>OTEL_EXPORTER_OTLP_*</c> environment variables. Without <c>OpenTelemetry:Exporter</c> nothing is added.
/// </summary>
public static class TelemetryExport
{
    /// <summary>The configuration section.</summary>
    public const string SectionName = "OpenTelemetry";

    /// <summary>The meters exported: the library's and the worker's.</summary>
    public static readonly string[] Meters = [HostLinkTelemetry.MeterName, Mqtt.MqttMetrics.MeterName];

    /// <summary>Adds the exporter <c>OpenTelemetry:Exporter</c> names, if any; an unknown name fails at start, naming the key.</summary>
    public static IServiceCollection AddTelemetryExport(this IServiceCollection services, IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        string key = SectionName + ":Exporter";
        string? exporter = configuration[key]?.Trim();
        if (string.IsNullOrEmpty(exporter) || exporter.Equals("None", StringComparison.OrdinalIgnoreCase))
        {
            return services;
        }

        bool console = exporter.Equals("Console", StringComparison.OrdinalIgnoreCase);
        if (!console && !exporter.Equals("Otlp", StringComparison.OrdinalIgnoreCase))
        {
            services.AddOptions<ExporterChoice>().Validate(_ => false, $"{key} '{exporter}' is not None, Console or Otlp.").ValidateOnStart();
            return services;
        }

        services.AddOpenTelemetry()
            .ConfigureResource(r => r.AddService(GatewayHost.ServiceName))
            .WithMetrics(m =>
            {
                m.AddMeter(Meters);
                _ = console ? m.AddConsoleExporter() : m.AddOtlpExporter();
            })
            .WithTracing(t =>
            {
                t.AddSource(HostLinkTelemetry.ActivitySourceName);
                _ = console ? t.AddConsoleExporter() : t.AddOtlpExporter();
            });
        return services;
    }

    /// <summary>The keys of the <c>OpenTelemetry</c> section, for the configuration check.</summary>
    public sealed class Settings
    {
        /// <summary><c>None</c> (default), <c>Console</c> or <c>Otlp</c>.</summary>
        public string? Exporter { get; set; }
    }

    /// <summary>Carries the start-up failure of an unknown exporter name.</summary>
    private sealed class ExporterChoice
    {
    }
}
