using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>The Sparkplug B output's log messages (event ids 1300–1399).</summary>
internal static partial class SparkplugLog
{
    [LoggerMessage(EventId = 1301, Level = LogLevel.Information, Message = "Sparkplug: edge node {GroupId}/{EdgeNodeId} online on {Broker} (bdSeq {BdSeq}, {Devices} device(s) born)")]
    public static partial void Online(ILogger logger, string broker, string groupId, string edgeNodeId, ulong bdSeq, int devices);

    [LoggerMessage(EventId = 1302, Level = LogLevel.Warning, Message = "Sparkplug: broker {Broker} unreachable ({Reason}); trying again in {RetryInSeconds:0.###} s")]
    public static partial void Unreachable(ILogger logger, string broker, string reason, double retryInSeconds);

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

    [LoggerMessage(EventId = 1312, Level = LogLevel.Warning, Message = "Sparkplug: primary host application {HostId} offline (STATE timestamp {Timestamp}); session ended (NDEATH, bdSeq {BdSeq}), reconnecting to {Broker} in {RetryInSeconds:0.###} s")]
    public static partial void PrimaryHostOffline(ILogger logger, string hostId, long? timestamp, ulong bdSeq, string broker, double retryInSeconds);

    [LoggerMessage(EventId = 1313, Level = LogLevel.Warning, Message = "Sparkplug: STATE on {Topic} ignored: {Why}")]
    public static partial void StateIgnored(ILogger logger, string topic, string why);

    [LoggerMessage(EventId = 1314, Level = LogLevel.Warning, Message = "Sparkplug: DCMD {Device} refused whole, {Writes} metric write(s), nothing sent to the PLC: {Reason}")]
    public static partial void CommandRefused(ILogger logger, string device, int writes, string reason);

    [LoggerMessage(EventId = 1315, Level = LogLevel.Error, Message = "Sparkplug: DCMD {Device} {Metric}: the gateway failed on the write; nothing more is sent for it")]
    public static partial void WriteCrashed(ILogger logger, Exception exception, string device, string metric);
}
