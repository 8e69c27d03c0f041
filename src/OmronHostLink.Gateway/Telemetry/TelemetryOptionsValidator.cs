using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Telemetry;

/// <summary>
/// Checks the <c>OpenTelemetry</c> section: the exporter's name, and with <c>Otlp</c> the endpoint variables, which the
/// exporter itself would ignore without a word, sending to its default instead.
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
internal sealed class TelemetryOptionsValidator(GatewayConfiguration gateway) : SectionValidator<TelemetryOptions>(gateway, TelemetryOptions.SectionName)
{
    /// <summary>The OTLP exporter's endpoint variables (read from the environment, or the configuration by the same name).</summary>
    private static readonly string[] OtlpEndpointKeys = ["OTEL_EXPORTER_OTLP_ENDPOINT", "OTEL_EXPORTER_OTLP_METRICS_ENDPOINT", "OTEL_EXPORTER_OTLP_TRACES_ENDPOINT"];

    /// <inheritdoc/>
    protected override void Check(TelemetryOptions options, List<string> failures)
    {
        if (options.Kind is not { } kind)
        {
            failures.Add($"{Section}:Exporter '{options.Exporter}' is not None, Console or Otlp.");
            return;
        }

        if (kind != TelemetryExporter.Otlp)
        {
            return;
        }

        foreach (string key in OtlpEndpointKeys)
        {
            string? value = Gateway.Root[key];
            if (string.IsNullOrWhiteSpace(value))
            {
                continue;
            }

            if (!Uri.TryCreate(value.Trim(), UriKind.Absolute, out Uri? uri) || (uri.Scheme != Uri.UriSchemeHttp && uri.Scheme != Uri.UriSchemeHttps))
            {
                failures.Add($"{key} '{value}' is not an http:// or https:// URL (such as http://collector.plant.local:4317).");
            }
            else if (HostSyntax.Problem(uri.IdnHost.Trim('[', ']')) is { } problem)
            {
                failures.Add($"{key} '{value}': '{uri.Host}' is not a host name or address: {problem}.");
            }
        }
    }
}
