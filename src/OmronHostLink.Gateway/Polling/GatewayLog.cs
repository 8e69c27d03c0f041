using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Polling;

/// <summary>The polling's log messages (source-generated), with structured fields: Link, Group, Unit, Address, Values.</summary>
internal static partial class GatewayLog
{
    /// <summary>Event ids, for filters and tests.</summary>
    public static class Events
    {
        /// <summary>A poll group's values.</summary>
        public const int Values = 1001;

        /// <summary>A PLC stopped answering (once per outage).</summary>
        public const int UnitDown = 1002;

        /// <summary>A PLC answers again.</summary>
        public const int UnitResumed = 1003;

        /// <summary>Another failed attempt during an outage (Debug).</summary>
        public const int UnitStillDown = 1004;

        /// <summary>A PLC stayed silent Demotion:After polls in a row and is demoted (once per demotion).</summary>
        public const int UnitDemoted = 1013;

        /// <summary>A demoted PLC answered its probe and is polled again.</summary>
        public const int UnitRestored = 1014;

        /// <summary>A poll group's read failed while the PLC answered (once per distinct failure).</summary>
        public const int GroupFailed = 1005;

        /// <summary>A failed poll group reads again.</summary>
        public const int GroupRecovered = 1006;

        /// <summary>A poll group's read failed in a way nobody expected (a bug; logged with the exception).</summary>
        public const int GroupCrashed = 1008;

        /// <summary>A poll took longer than intervals allowed; ticks were skipped (Debug).</summary>
        public const int TicksSkipped = 1007;

        /// <summary>A link starts polling.</summary>
        public const int LinkStarted = 1010;

        /// <summary>A link stopped.</summary>
        public const int LinkStopped = 1011;

        /// <summary>A link could not be set up.</summary>
        public const int LinkFailed = 1012;
    }

    [LoggerMessage(EventId = Events.Values, Level = LogLevel.Information, Message = "{Link}/{Group}: unit {Unit} {Address} = {Values}")]
    internal static partial void Values(ILogger logger, string link, string group, int unit, string address, string values);

    [LoggerMessage(EventId = Events.UnitDown, Level = LogLevel.Warning, Message = "link {Link}: PLC unit {Unit} not answering ({Reason}) — {Detail} Retrying in {RetryInSeconds:0.###} s, backing off up to {MaxBackoffSeconds:0.###} s.")]
    internal static partial void UnitDown(ILogger logger, string link, int unit, string reason, string detail, double retryInSeconds, double maxBackoffSeconds);

    [LoggerMessage(EventId = Events.UnitResumed, Level = LogLevel.Information, Message = "link {Link}: PLC unit {Unit} resumed after {OutageSeconds:0.#} s ({Attempts} failed attempts)")]
    internal static partial void UnitResumed(ILogger logger, string link, int unit, double outageSeconds, int attempts);

    [LoggerMessage(EventId = Events.UnitStillDown, Level = LogLevel.Debug, Message = "link {Link}: PLC unit {Unit} still not answering ({Reason}: {Detail}); next attempt in {RetryInSeconds:0.###} s")]
    internal static partial void UnitStillDown(ILogger logger, string link, int unit, string reason, string detail, double retryInSeconds);

    [LoggerMessage(EventId = Events.UnitDemoted, Level = LogLevel.Warning, Message = "link {Link}: PLC unit {Unit} demoted after {Polls} silent polls in a row ({Detail}); its tags are comm-error, and it is left alone for {PeriodSeconds:0.###} s between presence probes")]
    internal static partial void UnitDemoted(ILogger logger, string link, int unit, int polls, double periodSeconds, string detail);

    [LoggerMessage(EventId = Events.UnitRestored, Level = LogLevel.Information, Message = "link {Link}: PLC unit {Unit} restored: it answered its presence probe after {OutageSeconds:0.#} s without an answer, and is polled again")]
    internal static partial void UnitRestored(ILogger logger, string link, int unit, double outageSeconds);

    [LoggerMessage(EventId = Events.GroupFailed, Level = LogLevel.Warning, Message = "{Link}/{Group}: unit {Unit} {Address} cannot be read: {Detail}")]
    internal static partial void GroupFailed(ILogger logger, string link, string group, int unit, string address, string detail);

    [LoggerMessage(EventId = Events.GroupCrashed, Level = LogLevel.Error, Message = "{Link}/{Group}: unit {Unit} {Address}: unexpected failure")]
    internal static partial void GroupCrashed(ILogger logger, Exception exception, string link, string group, int unit, string address);

    [LoggerMessage(EventId = Events.GroupRecovered, Level = LogLevel.Information, Message = "{Link}/{Group}: unit {Unit} {Address} reads again")]
    internal static partial void GroupRecovered(ILogger logger, string link, string group, int unit, string address);

    [LoggerMessage(EventId = Events.TicksSkipped, Level = LogLevel.Debug, Message = "{Link}/{Group}: {Skipped} tick(s) skipped, the link was busy")]
    internal static partial void TicksSkipped(ILogger logger, string link, string group, long skipped);

    [LoggerMessage(EventId = Events.LinkStarted, Level = LogLevel.Information, Message = "link {Link}: polling {Groups} group(s) on {Description}")]
    internal static partial void LinkStarted(ILogger logger, string link, int groups, string description);

    [LoggerMessage(EventId = Events.LinkStopped, Level = LogLevel.Information, Message = "link {Link}: stopped after {Polls} polls ({Failures} failed)")]
    internal static partial void LinkStopped(ILogger logger, string link, long polls, long failures);

    [LoggerMessage(EventId = Events.LinkFailed, Level = LogLevel.Critical, Message = "link {Link}: cannot be set up; it will not be polled")]
    internal static partial void LinkFailed(ILogger logger, Exception exception, string link);
}
