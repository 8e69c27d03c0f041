using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Status;

/// <summary>The status page's log messages (source-generated).</summary>
internal static partial class StatusLog
{
    /// <summary>Event ids, for filters and tests.</summary>
    public static class Events
    {
        /// <summary>The page listens.</summary>
        public const int Started = 1401;

        /// <summary>The page stopped.</summary>
        public const int Stopped = 1402;

        /// <summary>The page cannot listen on its address and port: the gateway stops with exit code 2.</summary>
        public const int CannotListen = 1403;

        /// <summary>A link's frames are taken for its line trace (a page watches it).</summary>
        public const int TraceOn = 1404;

        /// <summary>No page watches a link's trace any more: its frames are no longer taken.</summary>
        public const int TraceOff = 1405;

        /// <summary>A request without a valid token was refused (Debug).</summary>
        public const int Refused = 1406;
    }

    [LoggerMessage(EventId = Events.Started, Level = LogLevel.Information, Message = "Status page: http://{EndPoint}/ ({Access}; read-only)")]
    public static partial void Started(ILogger logger, string endPoint, string access);

    [LoggerMessage(EventId = Events.Stopped, Level = LogLevel.Information, Message = "Status page: stopped")]
    public static partial void Stopped(ILogger logger);

    [LoggerMessage(EventId = Events.CannotListen, Level = LogLevel.Critical, Message = "Status:Address {Address} and Status:Port {Port}: the status page cannot listen there ({Reason}); choose another port or address, or stop the program that has it. Stopping.")]
    public static partial void CannotListen(ILogger logger, string address, int port, string reason);

    [LoggerMessage(EventId = Events.TraceOn, Level = LogLevel.Information, Message = "Status page: line trace of link {Link} on (a page watches it)")]
    public static partial void TraceOn(ILogger logger, string link);

    [LoggerMessage(EventId = Events.TraceOff, Level = LogLevel.Information, Message = "Status page: line trace of link {Link} off")]
    public static partial void TraceOff(ILogger logger, string link);

    [LoggerMessage(EventId = Events.Refused, Level = LogLevel.Debug, Message = "Status page: {Method} {Path} from {Remote} refused: {Reason}")]
    public static partial void Refused(ILogger logger, string method, string path, string remote, string reason);
}
