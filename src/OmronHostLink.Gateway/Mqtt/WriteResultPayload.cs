using System.Text.Json.Serialization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The JSON reply to a write command: <c>{"status":"done","tag":"plant/line1/0/setpoint","time":"…"}</c>, or
/// <c>"refused"</c> (nothing was sent to the PLC) or <c>"failed"</c> (the PLC or the line failed it) with an error and,
/// for a PLC end code, the code.
/// </summary>
internal sealed class WriteResultPayload
{
    /// <summary><c>done</c>, <c>refused</c> or <c>failed</c>.</summary>
    public required string Status { get; init; }

    /// <summary>The value topic of the tag the command was for.</summary>
    public required string Tag { get; init; }

    /// <summary>What went wrong; absent when done.</summary>
    public string? Error { get; init; }

    /// <summary>The PLC's end code (C-mode: two hex digits; FINS: four), when it refused the write.</summary>
    public string? EndCode { get; init; }

    /// <summary>When the worker finished with the command, UTC.</summary>
    [JsonConverter(typeof(UtcTimeJsonConverter))]
    public DateTimeOffset? Time { get; init; }
}
