using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>The MQTT output's log messages (source-generated), with structured fields: Broker, Topic, Queued, Reason.</summary>
internal static partial class MqttLog
{
    /// <summary>Event ids, for filters and tests.</summary>
    public static class Events
    {
        /// <summary>Connected to the broker (the first time).</summary>
        public const int Connected = 1100;

        /// <summary>The broker cannot be reached or refused the connection (once per outage).</summary>
        public const int Unreachable = 1101;

        /// <summary>Another failed attempt during an outage (Debug).</summary>
        public const int StillUnreachable = 1102;

        /// <summary>Connected again after an outage.</summary>
        public const int Reconnected = 1103;

        /// <summary>TLS certificate validation is off.</summary>
        public const int UntrustedCertificates = 1104;

        /// <summary>The broker refused a message (for example an ACL); it is dropped.</summary>
        public const int PublishRefused = 1105;

        /// <summary>The queue is full: an overflow episode starts.</summary>
        public const int QueueOverflowing = 1106;

        /// <summary>An overflow episode ended, with the number of messages dropped.</summary>
        public const int QueueOverflowed = 1107;

        /// <summary>The output stopped.</summary>
        public const int Stopped = 1108;

        /// <summary>The broker refused a command subscription.</summary>
        public const int SubscribeRefused = 1109;

        /// <summary>A write command completed.</summary>
        public const int WriteDone = 1110;

        /// <summary>A write command was refused before reaching the wire.</summary>
        public const int WriteRefused = 1111;

        /// <summary>A write command failed at the PLC or on the line.</summary>
        public const int WriteFailed = 1112;

        /// <summary>Write commands are accepted (logged at each connection).</summary>
        public const int WritesAccepted = 1113;

        /// <summary>A retained command was cleared (an empty retained message on a command topic): ignored.</summary>
        public const int RetainedCommandCleared = 1114;

        /// <summary>A write command failed inside the gateway (a bug; logged with the exception, answered as failed).</summary>
        public const int WriteCrashed = 1115;
    }

    [LoggerMessage(EventId = Events.Connected, Level = LogLevel.Information, Message = "MQTT: connected to {Broker} as {ClientId}; publishing under {Prefix}/")]
    internal static partial void Connected(ILogger logger, string broker, string clientId, string prefix);

    [LoggerMessage(EventId = Events.Unreachable, Level = LogLevel.Warning, Message = "MQTT: broker {Broker} not reachable ({Reason}); {Queued} message(s) wait. Retrying in {RetryInSeconds:0.###} s, backing off up to {MaxBackoffSeconds:0.###} s.")]
    internal static partial void Unreachable(ILogger logger, string broker, string reason, int queued, double retryInSeconds, double maxBackoffSeconds);

    [LoggerMessage(EventId = Events.StillUnreachable, Level = LogLevel.Debug, Message = "MQTT: broker {Broker} still not reachable ({Reason}); next attempt in {RetryInSeconds:0.###} s")]
    internal static partial void StillUnreachable(ILogger logger, string broker, string reason, double retryInSeconds);

    [LoggerMessage(EventId = Events.Reconnected, Level = LogLevel.Information, Message = "MQTT: connected to {Broker} again after {OutageSeconds:0.#} s ({Attempts} failed attempts); {Queued} message(s) to send")]
    internal static partial void Reconnected(ILogger logger, string broker, double outageSeconds, int attempts, int queued);

    [LoggerMessage(EventId = Events.UntrustedCertificates, Level = LogLevel.Warning, Message = "MQTT: Mqtt:Tls:AllowUntrustedCertificates is on: the broker's certificate is not checked, so anyone on the path to {Broker} can read and change what the worker sends and receives")]
    internal static partial void UntrustedCertificates(ILogger logger, string broker);

    [LoggerMessage(EventId = Events.PublishRefused, Level = LogLevel.Warning, Message = "MQTT: the broker refused a message on {Topic} ({ReasonCode}{ReasonString}); it is dropped")]
    internal static partial void PublishRefused(ILogger logger, string topic, string reasonCode, string reasonString);

    [LoggerMessage(EventId = Events.QueueOverflowing, Level = LogLevel.Information, Message = "MQTT: the queue is full ({Capacity} messages); the oldest are dropped until the broker takes messages again")]
    internal static partial void QueueOverflowing(ILogger logger, int capacity);

    [LoggerMessage(EventId = Events.QueueOverflowed, Level = LogLevel.Warning, Message = "MQTT: {Dropped} message(s) were dropped, the oldest first, while the queue was full ({Capacity} messages) for {Seconds:0.#} s")]
    internal static partial void QueueOverflowed(ILogger logger, long dropped, int capacity, double seconds);

    [LoggerMessage(EventId = Events.Stopped, Level = LogLevel.Information, Message = "MQTT: stopped; {Queued} message(s) not sent")]
    internal static partial void Stopped(ILogger logger, int queued);

    [LoggerMessage(EventId = Events.SubscribeRefused, Level = LogLevel.Warning, Message = "MQTT: the broker refused the subscription to {Filter} ({ReasonCode}); write commands on it will not arrive")]
    internal static partial void SubscribeRefused(ILogger logger, string filter, string reasonCode);

    [LoggerMessage(EventId = Events.WriteDone, Level = LogLevel.Information, Message = "MQTT write {Tag} {Address} = {Value}: done")]
    internal static partial void WriteDone(ILogger logger, string tag, string address, string value);

    [LoggerMessage(EventId = Events.WriteRefused, Level = LogLevel.Warning, Message = "MQTT write on {Topic} refused, nothing sent to the PLC: {Reason}")]
    internal static partial void WriteRefused(ILogger logger, string topic, string reason);

    [LoggerMessage(EventId = Events.WriteFailed, Level = LogLevel.Warning, Message = "MQTT write {Tag} {Address} = {Value} failed: {Detail}")]
    internal static partial void WriteFailed(ILogger logger, string tag, string address, string value, string detail);

    [LoggerMessage(EventId = Events.WritesAccepted, Level = LogLevel.Information, Message = "MQTT: accepting write commands for {Count} writable tag(s) on {Filters}")]
    internal static partial void WritesAccepted(ILogger logger, int count, string filters);

    [LoggerMessage(EventId = Events.RetainedCommandCleared, Level = LogLevel.Debug, Message = "MQTT: the retained command on {Topic} was cleared; nothing to do")]
    internal static partial void RetainedCommandCleared(ILogger logger, string topic);

    [LoggerMessage(EventId = Events.WriteCrashed, Level = LogLevel.Error, Message = "MQTT write on {Topic}: the gateway failed on the command; it is answered as failed")]
    internal static partial void WriteCrashed(ILogger logger, Exception exception, string topic);
}
