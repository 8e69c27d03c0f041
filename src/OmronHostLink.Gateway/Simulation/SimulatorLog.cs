using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Simulation;

/// <summary>The in-process simulator's log messages (source-generated).</summary>
internal static partial class SimulatorLog
{
    /// <summary>Event ids, for filters and tests.</summary>
    public static class Events
    {
        /// <summary>The in-process simulator listens.</summary>
        public const int Started = 1020;

        /// <summary>The in-process simulator stopped.</summary>
        public const int Stopped = 1021;

        /// <summary>The in-process simulator's port is taken: the gateway stops with exit code 2.</summary>
        public const int PortInUse = 1022;
    }

    [LoggerMessage(EventId = Events.Started, Level = LogLevel.Information, Message = "Simulator: virtual PLC (units {Units}) listening on {EndPoint}{FaultNote}")]
    public static partial void Started(ILogger logger, string units, string endPoint, string faultNote);

    [LoggerMessage(EventId = Events.Stopped, Level = LogLevel.Information, Message = "Simulator: stopped ({Faults})")]
    public static partial void Stopped(ILogger logger, string faults);

    [LoggerMessage(EventId = Events.PortInUse, Level = LogLevel.Critical, Message = "Simulator:Port {Port} on 127.0.0.1 is in use by another program (a second gateway?); choose another port or stop that program. Stopping.")]
    public static partial void PortInUse(ILogger logger, int port);
}
