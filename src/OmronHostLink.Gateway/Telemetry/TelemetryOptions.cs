namespace OmronHostLink.Gateway.Telemetry;

/// <summary>The <c>OpenTelemetry</c> section.</summary>
internal sealed class TelemetryOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "OpenTelemetry";

    /// <summary><c>None</c> (default), <c>Console</c> or <c>Otlp</c>.</summary>
    public string? Exporter { get; set; }

    /// <summary>The exporter <see cref="Exporter"/> names; <see cref="TelemetryExporter.None"/> when unset; null for a name that is none.</summary>
    public TelemetryExporter? Kind
        => string.IsNullOrWhiteSpace(Exporter) ? TelemetryExporter.None
            : Enum.TryParse(Exporter.Trim(), ignoreCase: true, out TelemetryExporter kind) && Enum.IsDefined(kind) && !int.TryParse(Exporter, out _) ? kind
            : null;
}

/// <summary>Where the meters and traces go.</summary>
internal enum TelemetryExporter
{
    /// <summary>Nowhere.</summary>
    None,

    /// <summary>Printed to the console.</summary>
    Console,

    /// <summary>To an OpenTelemetry collector (OTLP), configured by the <c>OTEL_EXPORTER_OTLP_*</c> variables.</summary>
    Otlp,
}
