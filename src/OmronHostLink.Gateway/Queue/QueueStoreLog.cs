using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Queue;

/// <summary>The log messages of what the outage queue keeps outside the process (event ids 1130-1139).</summary>
internal static partial class QueueStoreLog
{
    /// <summary>The event ids.</summary>
    public static class Events
    {
        /// <summary>The durable queue is open, with what the previous run left.</summary>
        public const int DurableQueueOpened = 1130;

        /// <summary>Messages the previous run left that no longer fit or were too old.</summary>
        public const int RestoredDropped = 1131;

        /// <summary>Messages dropped for waiting longer than Mqtt:DurableQueue:MaxAge.</summary>
        public const int Expired = 1132;

        /// <summary>The previous run ended with unsent messages and no durable queue.</summary>
        public const int PreviousLoss = 1133;

        /// <summary>The count of unsent messages cannot be kept.</summary>
        public const int RecordUnavailable = 1134;

        /// <summary>The durable queue cannot be written.</summary>
        public const int JournalFailed = 1135;

        /// <summary>The durable queue is written again.</summary>
        public const int JournalWritable = 1136;
    }

    [LoggerMessage(EventId = Events.DurableQueueOpened, Level = LogLevel.Information, Message = "MQTT: durable queue {Path}: {Restored} message(s) from the previous run are sent first")]
    public static partial void DurableQueueOpened(ILogger logger, string path, int restored);

    [LoggerMessage(EventId = Events.RestoredDropped, Level = LogLevel.Warning, Message = "MQTT: durable queue {Path}: {Dropped} message(s) from the previous run were over Mqtt:QueueCapacity or Mqtt:DurableQueue:MaxMegabytes and {Expired} older than Mqtt:DurableQueue:MaxAge; they are dropped, the oldest first")]
    public static partial void RestoredDropped(ILogger logger, string path, int dropped, int expired);

    [LoggerMessage(EventId = Events.Expired, Level = LogLevel.Warning, Message = "MQTT: {Count} message(s) waited longer than Mqtt:DurableQueue:MaxAge ({MaxAge}) and are dropped unsent")]
    public static partial void Expired(ILogger logger, long count, TimeSpan maxAge);

    [LoggerMessage(EventId = Events.PreviousLoss, Level = LogLevel.Warning, Message = "MQTT: the previous run ended with {Lost} message(s) the broker had not acknowledged, and no durable queue kept them: they may be lost (announced on {Topic}; Mqtt:DurableQueue:Enabled keeps them)")]
    public static partial void PreviousLoss(ILogger logger, long lost, string topic);

    [LoggerMessage(EventId = Events.RecordUnavailable, Level = LogLevel.Warning, Message = "MQTT: the count of unsent messages cannot be kept in {Path} ({Reason}); messages lost in a crash will not be announced. Set Mqtt:StateDirectory to a directory the gateway may write")]
    public static partial void RecordUnavailable(ILogger logger, string path, string reason);

    [LoggerMessage(EventId = Events.JournalFailed, Level = LogLevel.Error, Message = "MQTT: durable queue {Path} cannot be written ({Reason}); queued messages, from the one for {Topic} on, are kept in memory only, counted as at risk of loss, until it can take them")]
    public static partial void JournalFailed(ILogger logger, string path, string topic, string reason);

    [LoggerMessage(EventId = Events.JournalWritable, Level = LogLevel.Information, Message = "MQTT: durable queue {Path} is written again")]
    public static partial void JournalWritable(ILogger logger, string path);
}
