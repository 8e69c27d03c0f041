namespace OmronHostLink.Link;

/// <summary>
/// Attribute names on the library's measurements and spans: OpenTelemetry's own where one fits (<c>error.type</c>),
/// else under <c>hostlink.</c>.
/// </summary>
internal static class TelemetryTags
{
    /// <summary>The link's name (<see cref="HostLinkConnectionOptions.LinkName"/>): tells two clients apart.</summary>
    public const string LinkName = "hostlink.link.name";

    /// <summary>The unit number the command went to (0-31).</summary>
    public const string Unit = "hostlink.unit";

    /// <summary>The command's two-character header: RD, WD, FA…</summary>
    public const string Command = "hostlink.command";

    /// <summary>What a failed command or attempt ended with; absent on success (OpenTelemetry's attribute).</summary>
    public const string ErrorType = "error.type";

    /// <summary>Span only: where the link goes (port and settings, host:port).</summary>
    public const string Transport = "hostlink.transport";

    /// <summary>Span only: frames sent in all attempts of the command.</summary>
    public const string FramesSent = "hostlink.frames.sent";

    /// <summary>Span only: frames received in all attempts of the command.</summary>
    public const string FramesReceived = "hostlink.frames.received";

    /// <summary>Span only: attempts repeated.</summary>
    public const string Retries = "hostlink.retry_count";

    /// <summary>Span only: the Host Link end code of the answer (<c>00</c>, <c>01</c>…), when one came.</summary>
    public const string EndCode = "hostlink.end_code";

    /// <summary>Span only: the FINS response code of a FINS answer that reported an error (<c>0401</c>…).</summary>
    public const string FinsEndCode = "hostlink.fins.end_code";
}
