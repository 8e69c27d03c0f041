using Microsoft.Extensions.Logging;

namespace OmronHostLink;

/// <summary>Log messages of model detection, generated at compile time.</summary>
internal static partial class ModelLog
{
    [LoggerMessage(EventId = 20, Level = LogLevel.Information, Message = "Unit {Unit:D2} answered MM with {Code}: addresses and commands are checked against {Model}")]
    public static partial void Detected(ILogger logger, int unit, string code, string model);

    [LoggerMessage(EventId = 21, Level = LogLevel.Warning, Message = "Unit {Unit:D2}: {Reason}; addresses are checked against the CS/CJ sizes only (set HostLinkClientOptions.Model to name the model)")]
    public static partial void Unknown(ILogger logger, int unit, string reason);
}
