using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>The Sparkplug B output's log messages (event ids 1300–1399).</summary>
internal static partial class SparkplugLog
{
    [LoggerMessage(EventId = 1301, Level = LogLevel.Information, Message = "Sparkplug: edge node {GroupId}/{EdgeNodeId} online on {Broker} (bdSeq {BdSeq}, {Devices} device(s) born)")]
    public static partial void Online(ILogger logger, string broker, string groupId, string edgeNodeId, ulong bdSeq, int devices);

    [LoggerMessage(EventId = 1302, Level = LogLevel.Warning, Message = "Sparkplug: broker {Broker} {Problem} ({Reason}); {NextStep}")]
    public static partial void Unreachable(ILogger logger, string broker, string problem, string reason, string nextStep);

    [LoggerMessage(EventId = 1303, Level = LogLevel.Information, Message = "Sparkplug: stopped; NDEATH sent to {Broker}")]
    public static partial void Stopped(ILogger logger, string broker);

    [LoggerMessage(EventId = 1304, Level = LogLevel.Information, Message = "Sparkplug: rebirth requested (NCMD Node Control/Rebirth); publishing NBIRTH and DBIRTHs")]
    public static partial void RebirthRequested(ILogger logger);

    [LoggerMessage(EventId = 1305, Level = LogLevel.Warning, Message = "Sparkplug: {Topic} ignored: {Why}")]
    public static partial void CommandIgnored(ILogger logger, string topic, string why);

    [LoggerMessage(EventId = 1306, Level = LogLevel.Information, Message = "Sparkplug: DCMD {Device} {Metric}: wrote {Value} to {Address}")]
    public static partial void WriteDone(ILogger logger, string device, string metric, string address, string value);

    [LoggerMessage(EventId = 1307, Level = LogLevel.Warning, Message = "Sparkplug: DCMD {Device} {Metric} refused, nothing sent to the PLC: {Reason}")]
    public static partial void WriteRefused(ILogger logger, string device, string metric, string reason);

    [LoggerMessage(EventId = 1308, Level = LogLevel.Warning, Message = "Sparkplug: DCMD {Device} {Metric}: writing {Value} to {Address} failed: {Error}")]
    public static partial void WriteFailed(ILogger logger, string device, string metric, string address, string value, string error);

    [LoggerMessage(EventId = 1309, Level = LogLevel.Warning, Message = "Sparkplug: TLS certificate checks are off for {Broker} (Sparkplug:Tls:AllowUntrustedCertificates); anyone on the path can read and change the data")]
    public static partial void UntrustedCertificates(ILogger logger, string broker);

    [LoggerMessage(EventId = 1310, Level = LogLevel.Information, Message = "Sparkplug: connected to {Broker} (bdSeq {BdSeq}); waiting for the primary host application {HostId} to be online ({Topic}) before the births")]
    public static partial void WaitingForPrimaryHost(ILogger logger, string broker, ulong bdSeq, string hostId, string topic);

    [LoggerMessage(EventId = 1311, Level = LogLevel.Information, Message = "Sparkplug: primary host application {HostId} online (STATE timestamp {Timestamp}); publishing the births")]
    public static partial void PrimaryHostOnline(ILogger logger, string hostId, long? timestamp);

    [LoggerMessage(EventId = 1312, Level = LogLevel.Warning, Message = "Sparkplug: session on {Broker} ended: {Reason}; NDEATH (bdSeq {BdSeq}) sent, disconnected; {NextStep}")]
    public static partial void PrimaryHostOffline(ILogger logger, string reason, ulong bdSeq, string broker, string nextStep);

    [LoggerMessage(EventId = 1313, Level = LogLevel.Warning, Message = "Sparkplug: STATE on {Topic} ignored: {Why}")]
    public static partial void StateIgnored(ILogger logger, string topic, string why);

    [LoggerMessage(EventId = 1314, Level = LogLevel.Warning, Message = "Sparkplug: DCMD {Device} refused whole, {Writes} metric write(s), nothing sent to the PLC: {Reason}")]
    public static partial void CommandRefused(ILogger logger, string device, int writes, string reason);

    [LoggerMessage(EventId = 1315, Level = LogLevel.Error, Message = "Sparkplug: DCMD {Device} {Metric}: the gateway failed on the write; nothing more is sent for it")]
    public static partial void WriteCrashed(ILogger logger, Exception exception, string device, string metric);

    [LoggerMessage(EventId = 1316, Level = LogLevel.Debug, Message = "Sparkplug: broker {Broker} {Problem} ({Reason}); {NextStep}")]
    public static partial void StillUnreachable(ILogger logger, string broker, string problem, string reason, string nextStep);

    [LoggerMessage(EventId = 1318, Level = LogLevel.Error, Message = "Sparkplug: another edge node publishes as {GroupId}/{EdgeNodeId} on {Broker} (an NBIRTH this gateway did not send, bdSeq {BdSeq}); two gateways with one Sparkplug:GroupId and Sparkplug:EdgeNodeId? Host applications see one node that keeps being born again. Logged once a connection")]
    public static partial void ForeignBirth(ILogger logger, string groupId, string edgeNodeId, string broker, string bdSeq);

    [LoggerMessage(EventId = 1320, Level = LogLevel.Warning, Message = "Sparkplug: the store of changes is full (Sparkplug:StoreAndForward:Capacity {Capacity} changes, or MaxMegabytes {MaxMegabytes}); the oldest are dropped, counted in the node metric Store and Forward/Dropped")]
    public static partial void StoreOverflowing(ILogger logger, int capacity, int maxMegabytes);

    [LoggerMessage(EventId = 1321, Level = LogLevel.Warning, Message = "Sparkplug: {Dropped} change(s) were dropped, the oldest first, while the store was full; {Total} dropped since the start (node metric Store and Forward/Dropped)")]
    public static partial void StoreOverflowed(ILogger logger, long dropped, long total);

    [LoggerMessage(EventId = 1322, Level = LogLevel.Warning, Message = "Sparkplug: {Count} change(s) were kept longer than Sparkplug:StoreAndForward:MaxAge ({MaxAge}) and are dropped unsent")]
    public static partial void StoreExpired(ILogger logger, long count, TimeSpan maxAge);

    [LoggerMessage(EventId = 1323, Level = LogLevel.Information, Message = "Sparkplug: durable store {Path}: {Restored} change(s) from the previous run are published as history after the next births")]
    public static partial void StoreOpened(ILogger logger, string path, int restored);

    [LoggerMessage(EventId = 1324, Level = LogLevel.Warning, Message = "Sparkplug: durable store {Path}: {Dropped} change(s) from the previous run were over Sparkplug:StoreAndForward:Capacity or MaxMegabytes and {Expired} older than MaxAge; they are dropped, the oldest first")]
    public static partial void StoreRestoredDropped(ILogger logger, string path, int dropped, int expired);

    [LoggerMessage(EventId = 1325, Level = LogLevel.Warning, Message = "Sparkplug: the previous run ended with {Lost} change(s) kept in memory only: they are lost (Sparkplug:StoreAndForward:Durable keeps them), and counted in the node metric Store and Forward/Dropped")]
    public static partial void StorePreviousLoss(ILogger logger, long lost);

    [LoggerMessage(EventId = 1326, Level = LogLevel.Warning, Message = "Sparkplug: the count of changes kept in memory cannot be kept in {Path} ({Reason}); changes lost in a crash will not be announced. Set Sparkplug:StateDirectory to a directory the gateway may write")]
    public static partial void StoreRecordUnavailable(ILogger logger, string path, string reason);
}
