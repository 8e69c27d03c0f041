using System.Diagnostics.Metrics;
using Microsoft.Extensions.Logging;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>What the link needs to know about the line: timing, the PLC's turnaround, echo, telemetry and the clock.</summary>
internal sealed class HostLinkConnectionOptions
{
    /// <summary>The line's character timing, used when the transport does not know it (TCP, streams).</summary>
    public LineTiming LineTiming { get; init; } = LineTiming.Default;

    /// <summary>The time the PLC (and anything between) may take to start answering a frame, on top of its wire time.</summary>
    public TimeSpan TurnaroundAllowance { get; init; } = TimeSpan.FromMilliseconds(300);

    /// <summary>The line echoes what we send (2-wire RS-485): read and check our own frames back before each answer.</summary>
    public bool LocalEcho { get; init; }

    /// <summary>Where the link logs; null for nowhere.</summary>
    public ILoggerFactory? LoggerFactory { get; init; }

    /// <summary>Where the link's meter comes from; null for the library's shared static meter.</summary>
    public IMeterFactory? MeterFactory { get; init; }

    /// <summary>The link's name in metrics and traces; null for the port name or the transport's description.</summary>
    public string? LinkName { get; init; }

    /// <summary>The least time between the end of one exchange and the next command on the line; zero for none.</summary>
    public TimeSpan SendInterval { get; init; }

    /// <summary>Longer gaps before commands to particular units (unit number to gap); the longer of this and <see cref="SendInterval"/> applies.</summary>
    public IReadOnlyDictionary<int, TimeSpan>? UnitSendIntervals { get; init; }

    /// <summary>How a Serial Communications Unit in a Host Link-compatible mode frames its answers, checked frame by frame; null for any framing.</summary>
    public CompatibleModeFraming? AnswerFraming { get; init; }

    /// <summary>Sends a TS with a fresh token behind every C-mode answer and takes the answer only when the token comes back next.</summary>
    public bool VerifyAnswers { get; init; }

    /// <summary>A capture file every frame is written to (pcap or JSON lines by its name); null for none.</summary>
    public string? TraceFile { get; init; }

    /// <summary>The clock deadlines run on.</summary>
    public TimeProvider TimeProvider { get; init; } = TimeProvider.System;

    /// <summary>The gap to keep before a command to <paramref name="unit"/>.</summary>
    public TimeSpan SendIntervalFor(int unit)
        => UnitSendIntervals is { } units && units.TryGetValue(unit, out TimeSpan gap) && gap > SendInterval ? gap : SendInterval;
}
