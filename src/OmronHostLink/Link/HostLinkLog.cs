using Microsoft.Extensions.Logging;

namespace OmronHostLink.Link;

/// <summary>Log messages of the link, generated at compile time.</summary>
internal static partial class HostLinkLog
{
    [LoggerMessage(EventId = 1, Level = LogLevel.Trace, Message = "{Transport} {Direction} {Frame}")]
    public static partial void Frame(ILogger logger, string transport, string direction, string frame);

    [LoggerMessage(EventId = 2, Level = LogLevel.Debug, Message = "Unit {Unit:D2} {Header} completed in {ElapsedMs:0.0} ms ({Frames} frames)")]
    public static partial void Transaction(ILogger logger, int unit, string header, double elapsedMs, int frames);

    [LoggerMessage(EventId = 3, Level = LogLevel.Warning, Message = "Unit {Unit:D2} {Header} failed ({Reason}); retry {Attempt} of {Retries}")]
    public static partial void Retry(ILogger logger, int unit, string header, string reason, int attempt, int retries);

    [LoggerMessage(EventId = 4, Level = LogLevel.Debug, Message = "Resynchronising the link after a failed exchange with unit {Unit:D2}: discarded {Discarded} bytes, fence {Outcome}")]
    public static partial void Resync(ILogger logger, int unit, long discarded, ResyncOutcome outcome);

    [LoggerMessage(EventId = 5, Level = LogLevel.Information, Message = "Opened {Transport}")]
    public static partial void Opened(ILogger logger, string transport);

    [LoggerMessage(EventId = 6, Level = LogLevel.Warning, Message = "Lost {Transport}: {Reason}")]
    public static partial void Lost(ILogger logger, string transport, string reason);

    [LoggerMessage(EventId = 7, Level = LogLevel.Debug, Message = "Unit {Unit:D2} {Header} failed: {Reason}")]
    public static partial void Failed(ILogger logger, int unit, string header, string reason);

    [LoggerMessage(EventId = 8, Level = LogLevel.Warning, Message = "Answers on {Link} come back faster than the configured line allows: a TS check came back in {ElapsedMs:0.0} ms, where {BaudRate} bps needs at least {EarliestMs:0.0} ms. Set Serial:BaudRate (in code, HostLinkClientOptions.LineTiming) to the line's real speed; until then answers are not checked for arriving before their command could have been answered.")]
    public static partial void FasterThanConfigured(ILogger logger, string link, double elapsedMs, int baudRate, double earliestMs);

    [LoggerMessage(EventId = 9, Level = LogLevel.Debug, Message = "{Link}: a frame arrived while no command was outstanding ({Bytes} bytes held); the link fences before the next command")]
    public static partial void ArrivedWhileIdle(ILogger logger, string link, int bytes);
}
