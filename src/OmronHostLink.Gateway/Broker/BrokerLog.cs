using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Broker;

/// <summary>The log messages of a broker connection, the same for every output (event ids 1140-1149).</summary>
internal static partial class BrokerLog
{
    /// <summary>The event ids.</summary>
    public static class Events
    {
        /// <summary>Connected to a server of the list other than the one used last.</summary>
        public const int ServerInUse = 1140;

        /// <summary>Another client connects with this client id: the broker hands it our session.</summary>
        public const int DuplicateIdentity = 1141;

        /// <summary>The same, again, within one episode.</summary>
        public const int DuplicateIdentityAgain = 1142;

        /// <summary>No answer to a ping: the connection is taken as lost.</summary>
        public const int PingUnanswered = 1143;
    }

    [LoggerMessage(EventId = Events.ServerInUse, Level = LogLevel.Information, Message = "{Output}: using {Server}, server {Number} of {Count}")]
    public static partial void ServerInUse(ILogger logger, string output, string server, int number, int count);

    [LoggerMessage(EventId = Events.DuplicateIdentity, Level = LogLevel.Error, Message = "{Output}: another client is connecting to {Broker} with this gateway's client id {ClientId} and the broker hands it the session ({Evidence}); two gateways with one {Key}? Reconnecting with backoff, in {RetryInSeconds:0.###} s, up to {MaxBackoffSeconds:0.###} s; not logged again until a connection lasts {StableSeconds:0.###} s")]
    public static partial void DuplicateIdentity(ILogger logger, string output, string broker, string clientId, string evidence, string key, double retryInSeconds, double maxBackoffSeconds, double stableSeconds);

    [LoggerMessage(EventId = Events.DuplicateIdentityAgain, Level = LogLevel.Debug, Message = "{Output}: the session of client id {ClientId} on {Broker} was taken over again; retrying in {RetryInSeconds:0.###} s")]
    public static partial void DuplicateIdentityAgain(ILogger logger, string output, string broker, string clientId, double retryInSeconds);

    [LoggerMessage(EventId = Events.PingUnanswered, Level = LogLevel.Debug, Message = "{Output}: {Broker} did not answer a ping within {Seconds:0.###} s; the connection is taken as lost")]
    public static partial void PingUnanswered(ILogger logger, string output, string broker, double seconds);
}
