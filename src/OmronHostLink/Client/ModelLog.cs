using Microsoft.Extensions.Logging;

namespace OmronHostLink;

/// <summary>Log messages of model detection, generated at compile time.</summary>
internal static partial class ModelLog
{
    [LoggerMessage(EventId = 20, Level = LogLevel.Information, Message = "Unit {Unit:D2} answered MM with {Code}: addresses and commands are checked against {Model}")]
    public static partial void Detected(ILogger logger, int unit, string code, string model);

    [LoggerMessage(EventId = 21, Level = LogLevel.Warning, Message = "Unit {Unit:D2}: {Reason}; addresses are checked against the CS/CJ sizes only (set HostLinkClientOptions.Model to name the model)")]
    public static partial void Unknown(ILogger logger, int unit, string reason);

    [LoggerMessage(EventId = 22, Level = LogLevel.Information, Message = "Unit {Unit:D2} answered MM with {Code} ({Model}): its planned reads use {Reads} (UseCompoundRead Auto)")]
    public static partial void NamedForCompoundRead(ILogger logger, int unit, string code, string model, string reads);

    [LoggerMessage(EventId = 23, Level = LogLevel.Information, Message = "Unit {Unit:D2}: {Reason}; its planned reads use area reads (UseCompoundRead Auto: QQ only where the model is known to have it; set Model, or UseCompoundRead On)")]
    public static partial void UnknownForCompoundRead(ILogger logger, int unit, string reason);

    [LoggerMessage(EventId = 24, Level = LogLevel.Warning, Message = "Unit {Unit:D2} answered {Command} with {EndCode}, though {Claim}: it is read with area reads from now on (this read included); set UseCompoundRead Off to skip QQ")]
    public static partial void CompoundReadRefused(ILogger logger, int unit, string command, string endCode, string claim);
}
