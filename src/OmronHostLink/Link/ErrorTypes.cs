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

    /// <summary>
    /// The name for <paramref name="failure"/>: one of the constants here; the name an end code gives itself
    /// (<see cref="EndCodeException.ErrorType"/>); else the exception's type name, as OpenTelemetry advises.
    /// </summary>
    public static string Of(Exception failure) => failure switch
    {
        HostLinkTimeoutException => Timeout,
        HostLinkFrameException => FrameError,
        HostLinkConnectionException => Connection,
        OperationCanceledException => Cancelled,
        EndCodeException e => e.ErrorType,
        _ => failure.GetType().FullName ?? "_OTHER",
    };
}
