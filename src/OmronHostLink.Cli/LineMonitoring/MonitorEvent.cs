namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>What the monitor reports: an exchange, a frame no exchange explains, or bytes that do not frame.</summary>
internal abstract record MonitorEvent
{
    /// <summary>A command and its answer (or its lack of one).</summary>
    public sealed record Exchanged(MonitoredExchange Exchange) : MonitorEvent;

    /// <summary>A sound frame that belongs to no exchange: an answer with no command, a CR out of turn.</summary>
    public sealed record Stray(MonitoredFrame Frame) : MonitorEvent;

    /// <summary>Bytes that do not frame.</summary>
    public sealed record Noise(MonitoredFrame Frame) : MonitorEvent;
}
