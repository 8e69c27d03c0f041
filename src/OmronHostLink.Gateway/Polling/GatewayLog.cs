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

        /// <summary>A link's plan: its tags, scan classes and the share of the line's time they need (at start).</summary>
        public const int LinkPlanned = 1015;

        /// <summary>A scan class's plan: the reads one unit's tags at one interval make each cycle (at start, and when it changes).</summary>
        public const int ScanPlanned = 1016;

        /// <summary>A scan class's planned cycle is longer than its interval on this line.</summary>
        public const int ScanCannotFit = 1017;

        /// <summary>A link's scan classes together need more than the line's time.</summary>
        public const int LinkOverloaded = 1018;

        /// <summary>A scan class overran its interval cycle after cycle (once per episode, with the measured period).</summary>
        public const int ScanOverrun = 1019;

        /// <summary>A scan class that overran keeps its interval again.</summary>
        public const int ScanKeepsUp = 1024;

        /// <summary>Some tags of a scan class failed alone: they are read on their own, the others together.</summary>
        public const int ScanSplit = 1025;

        /// <summary>A tag read on its own after a failure reads again and rejoins its scan class.</summary>
        public const int ScanRejoined = 1026;

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

    [LoggerMessage(EventId = Events.LinkPlanned, Level = LogLevel.Information, Message = "link {Link}: {Tags} tag(s) in {Classes} scan class(es) on {Line}: {Reads} read(s) and {Characters} characters a cycle in all, {Load:P0} of the line's time")]
    internal static partial void LinkPlanned(ILogger logger, string link, int tags, int classes, string line, int reads, int characters, double load);

    [LoggerMessage(EventId = Events.ScanPlanned, Level = LogLevel.Information, Message = "link {Link}: unit {Unit} every {Interval}: {Tags} tag(s) in {Plan}; {CycleMs:0} ms a cycle on the line ({LineMs:0} ms of its own){Note}")]
    internal static partial void ScanPlanned(ILogger logger, string link, int unit, string interval, int tags, string plan, double cycleMs, double lineMs, string note);

    [LoggerMessage(EventId = Events.ScanCannotFit, Level = LogLevel.Warning, Message = "link {Link}: unit {Unit}'s {Tags} tag(s) every {Interval} need {EstimatedMs:0} ms a cycle on this line ({LineMs:0} ms of their own, {Plan}; the rest is the host's hand-over of each read and waits for the link's other scan classes), more than their interval: they will be read every {EstimatedMs:0} ms at best. A longer Interval, fewer tags at this rate, QQ (UseCompoundRead) or a faster line would fit them")]
    internal static partial void ScanCannotFit(ILogger logger, string link, int unit, int tags, string interval, double estimatedMs, double lineMs, string plan);

    [LoggerMessage(EventId = Events.LinkOverloaded, Level = LogLevel.Warning, Message = "link {Link}: its scan classes need {Load:P0} of the line's time ({Detail}): the line cannot read every tag at its interval, and cycles will overrun")]
    internal static partial void LinkOverloaded(ILogger logger, string link, double load, string detail);

    [LoggerMessage(EventId = Events.ScanOverrun, Level = LogLevel.Warning, Message = "link {Link}: unit {Unit}'s {Tags} tag(s) every {Interval} are read every {PeriodMs:0} ms (measured over the last {Cycles} cycles; a cycle was planned to take {EstimatedMs:0} ms, the last took {LastMs:0} ms): the line cannot keep their interval")]
    internal static partial void ScanOverrun(ILogger logger, string link, int unit, int tags, string interval, double periodMs, int cycles, double estimatedMs, double lastMs);

    [LoggerMessage(EventId = Events.ScanKeepsUp, Level = LogLevel.Information, Message = "link {Link}: unit {Unit}'s tags every {Interval} keep their interval again")]
    internal static partial void ScanKeepsUp(ILogger logger, string link, int unit, string interval);

    [LoggerMessage(EventId = Events.ScanSplit, Level = LogLevel.Information, Message = "link {Link}: unit {Unit} every {Interval}: {Failed} of {Tags} tag(s) cannot be read ({Names}); they are read on their own until they read again, the others together")]
    internal static partial void ScanSplit(ILogger logger, string link, int unit, string interval, int failed, int tags, string names);

    [LoggerMessage(EventId = Events.ScanRejoined, Level = LogLevel.Information, Message = "{Link}/{Group}: reads again, and is read with the other tags of unit {Unit} every {Interval} again")]
    internal static partial void ScanRejoined(ILogger logger, string link, string group, int unit, string interval);

    [LoggerMessage(EventId = Events.LinkStarted, Level = LogLevel.Information, Message = "link {Link}: polling {Groups} group(s) on {Description}")]
    internal static partial void LinkStarted(ILogger logger, string link, int groups, string description);

    [LoggerMessage(EventId = Events.LinkStopped, Level = LogLevel.Information, Message = "link {Link}: stopped after {Polls} polls ({Failures} failed)")]
    internal static partial void LinkStopped(ILogger logger, string link, long polls, long failures);

    [LoggerMessage(EventId = Events.LinkFailed, Level = LogLevel.Critical, Message = "link {Link}: cannot be set up; it will not be polled")]
    internal static partial void LinkFailed(ILogger logger, Exception exception, string link);
}
