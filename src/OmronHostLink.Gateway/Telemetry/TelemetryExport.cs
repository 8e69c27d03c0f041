using Microsoft.Extensions.DependencyInjection;
using OmronHostLink.Gateway.Configuration;
using OpenTelemetry.Metrics;
using OpenTelemetry.Resources;
using OpenTelemetry.Trace;

namespace OmronHostLink.Gateway.Telemetry;

/// <summary>
/// Opt-in OpenTelemetry export of the library's and the worker's meters (and the library's traces): <c>Console</c>
/// prints them (to look at), <c>Otlp</c> sends them to a collector configured by the standard
/// <c>OTEL_EXPORTER_OTLP_*</c> environment variables. Without <c>OpenTelemetry:Exporter</c> nothing is added.
/// </summary>
internal static class TelemetryExport
{
    /// <summary>The meters exported: the library's and the worker's.</summary>
    public static readonly string[] Meters = [HostLinkTelemetry.MeterName, GatewayNames.Meter];

    /// <summary>
    /// Adds the <c>OpenTelemetry</c> section's check and the exporter <c>OpenTelemetry:Exporter</c> names, if any; an
    /// unknown name fails at start, naming the key.
    /// </summary>
    public static IServiceCollection AddTelemetryExport(this IServiceCollection services, GatewayConfiguration gateway)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        new TelemetryOptionsValidator(gateway).AddTo(services);
        var options = new TelemetryOptions();
        gateway.Bind(TelemetryOptions.SectionName, options);
        if (options.Kind is not { } kind || kind == TelemetryExporter.None)
        {
            return services;
        }

        bool console = kind == TelemetryExporter.Console;
        services.AddOpenTelemetry()
            .ConfigureResource(r => r.AddService(GatewayNames.Service))
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
}
