using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Options;
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
public static class TelemetryExport
{
    /// <summary>The configuration section.</summary>
    public const string SectionName = "OpenTelemetry";

    /// <summary>The meters exported: the library's and the worker's.</summary>
    public static readonly string[] Meters = [HostLinkTelemetry.MeterName, GatewayNames.Meter];

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

    /// <summary>The OTLP exporter's endpoint variables (read from the environment, or the configuration by the same name).</summary>
    public static readonly string[] OtlpEndpointKeys = ["OTEL_EXPORTER_OTLP_ENDPOINT", "OTEL_EXPORTER_OTLP_METRICS_ENDPOINT", "OTEL_EXPORTER_OTLP_TRACES_ENDPOINT"];

    /// <summary>
    /// The OTLP endpoints that are no URL the exporter can send to, each named by its variable. The exporter itself
    /// ignores such a value without a word and sends to its default instead.
    /// </summary>
    public static IEnumerable<string> EndpointProblems(IConfiguration configuration)
    {
        ArgumentNullException.ThrowIfNull(configuration);
        if (!string.Equals(configuration[SectionName + ":Exporter"]?.Trim(), "Otlp", StringComparison.OrdinalIgnoreCase))
        {
            yield break;
        }

        foreach (string key in OtlpEndpointKeys)
        {
            string? value = configuration[key];
            if (string.IsNullOrWhiteSpace(value))
            {
                continue;
            }

            if (!Uri.TryCreate(value.Trim(), UriKind.Absolute, out Uri? uri) || (uri.Scheme != Uri.UriSchemeHttp && uri.Scheme != Uri.UriSchemeHttps))
            {
                yield return $"{key} '{value}' is not an http:// or https:// URL (such as http://collector.plant.local:4317).";
            }
            else if (HostSyntax.Problem(uri.IdnHost.Trim('[', ']')) is { } problem)
            {
                yield return $"{key} '{value}': '{uri.Host}' is not a host name or address: {problem}.";
            }
        }
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
