using System.Runtime.InteropServices;

namespace OmronHostLink.Com;

/// <summary>
/// The HRESULTs a failure is raised with, which VB sees as <c>Err.Number</c> (the type library lists them as the
/// <c>PlcError</c> enum): one for each kind of failure the library reports, and a range for the PLC's end codes, so a
/// script tells a refused write, a silent PLC, a damaged answer and a lost port apart. <c>Err.Description</c> is the
/// library's message. All are in FACILITY_ITF (<c>vbObjectError</c> = &amp;H80040000).
/// </summary>
public static class PlcErrors
{
    /// <summary>No answer in time, after the read retries (<see cref="HostLinkTimeoutException"/>).</summary>
    public const int Timeout = unchecked((int)0x80040201);

    /// <summary>A damaged answer, or one that is not the answer to the command (<see cref="HostLinkFrameException"/>).</summary>
    public const int Frame = unchecked((int)0x80040202);

    /// <summary>The port or socket could not be opened or was lost (<see cref="HostLinkConnectionException"/>).</summary>
    public const int Connection = unchecked((int)0x80040203);

    /// <summary>A call that needs the link before <c>Open</c> or after <c>Close</c>, or a setting changed while open.</summary>
    public const int NotOpen = unchecked((int)0x80040204);

    /// <summary>An address, count, value, tag, mode or connection string that cannot be used; nothing was sent.</summary>
    public const int InvalidArgument = unchecked((int)0x80040205);

    /// <summary>Any other failure the library reports (<see cref="HostLinkException"/>).</summary>
    public const int HostLink = unchecked((int)0x80040206);

    /// <summary>The first of the C-mode end codes: end code NN is <c>EndCode + NN</c>.</summary>
    public const int EndCode = unchecked((int)0x80041000);

    /// <summary>C-mode end code 01: the command cannot run in RUN mode (writes need MONITOR or PROGRAM).</summary>
    public const int EndCodeRunMode = EndCode + (int)OmronHostLink.EndCode.NotExecutableInRunMode;

    /// <summary>The first of the FINS end codes: main code MM and sub code SS are <c>FinsEndCode + &amp;HMMSS</c> (flags removed).</summary>
    public const int FinsEndCode = unchecked((int)0x80048000);

    /// <summary>The HRESULT for a failure of the library or of the arguments.</summary>
    /// <param name="exception">What the library threw.</param>
    /// <returns>The HRESULT; an exception of another kind keeps its own.</returns>
    public static int HResultOf(Exception exception) => exception switch
    {
        HostLinkEndCodeException e => EndCode + (int)e.EndCode,
        FinsEndCodeException e => FinsEndCode + e.EndCode.Code,
        HostLinkTimeoutException => Timeout,
        HostLinkFrameException => Frame,
        HostLinkConnectionException => Connection,
        HostLinkException => HostLink,
        ObjectDisposedException => NotOpen,
        ArgumentException or FormatException or NotSupportedException or OverflowException or InvalidCastException => InvalidArgument,
        _ => exception.HResult,
    };

    /// <summary>The COM error to raise for <paramref name="exception"/>: its HRESULT and the library's message.</summary>
    /// <param name="exception">What the library threw.</param>
    /// <returns>An exception whose HRESULT and message the COM caller sees as <c>Err.Number</c> and <c>Err.Description</c>.</returns>
    internal static COMException ToComError(Exception exception)
        => new(Description(exception), HResultOf(exception)) { Source = Plc.ProgId };

    /// <summary>
    /// The message, on one line for a message box: an argument's message without the "(Parameter 'x')" and "Actual
    /// value was …" that .NET appends, since the library's message already names the value.
    /// </summary>
    private static string Description(Exception exception)
    {
        string message = exception.Message;
        if (exception is ArgumentException { ParamName: { } name })
        {
            int suffix = message.IndexOf($" (Parameter '{name}')", StringComparison.Ordinal);
            message = suffix >= 0 ? message.Substring(0, suffix) : message;
        }

        return message;
    }

    /// <summary>A failure raised by the server itself (a call before <c>Open</c>, a bad argument).</summary>
    internal static COMException Raise(int hresult, string message) => new(message, hresult) { Source = Plc.ProgId };
}
