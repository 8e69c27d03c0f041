using System.Globalization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Link;

/// <summary>
/// The <c>error.type</c> of a failed command or attempt: a short, low-cardinality name for what ended it, so that a
/// dashboard can group failures without a tag per message.
/// </summary>
internal static class ErrorTypes
{
    /// <summary>No answer within the deadline (or no echo of the resynchronisation fence).</summary>
    public const string Timeout = "timeout";

    /// <summary>A damaged or unexpected frame: bad FCS, wrong unit or header, wrong length.</summary>
    public const string FrameError = "frame_error";

    /// <summary>The transport could not be opened or was lost.</summary>
    public const string Connection = "connection";

    /// <summary>The caller's token was cancelled.</summary>
    public const string Cancelled = "cancelled";

    private static readonly Dictionary<EndCode, string> EndCodeNames = EndCodes.All.ToDictionary(c => c, c => c.ToString());

    /// <summary>
    /// The name for <paramref name="failure"/>: one of the constants here; a C-mode end code's name
    /// (<c>NotExecutableInRunMode</c>); <c>fins_</c> and a FINS response code without its flags (<c>fins_0401</c>);
    /// else the exception's type name, as OpenTelemetry advises.
    /// </summary>
    public static string Of(Exception failure) => failure switch
    {
        HostLinkTimeoutException => Timeout,
        HostLinkFrameException => FrameError,
        HostLinkConnectionException => Connection,
        OperationCanceledException => Cancelled,
        HostLinkEndCodeException e => Name(e.EndCode),
        FinsEndCodeException e => Name(e.EndCode),
        _ => failure.GetType().FullName ?? "_OTHER",
    };

    /// <summary>The end code's name, or <c>end_code_</c> and its two characters for one the manuals do not define.</summary>
    public static string Name(EndCode code)
        => EndCodeNames.TryGetValue(code, out string? name) ? name : "end_code_" + code.ToCode();

    /// <summary><c>fins_</c> and the response code without its relay and CPU-error flags.</summary>
    public static string Name(FinsEndCode code) => "fins_" + code.Code.ToString("X4", CultureInfo.InvariantCulture);
}
