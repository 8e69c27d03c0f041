using System.Text.Json.Serialization;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The JSON reply to a write command: <c>{"status":"done","tag":"plant/line1/0/setpoint","time":"…"}</c>, or
/// <c>"refused"</c> (nothing was sent to the PLC) or <c>"failed"</c> (the PLC or the line failed it) with an error and,
/// for a PLC end code, the code.
/// </summary>
public sealed class WriteResultPayload
{
    /// <summary>The status of a write that the PLC completed (end code 00).</summary>
    public const string Done = "done";

    /// <summary>The status of a command refused before anything reached the wire.</summary>
    public const string Refused = "refused";

    /// <summary>The status of a write the PLC refused (an end code) or that did not complete (timeout, lost link).</summary>
    public const string Failed = "failed";

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
