namespace OmronHostLink.Cli;

/// <summary>The process exit codes of every command.</summary>
internal static class ExitCodes
{
    /// <summary>The command did what was asked.</summary>
    public const int Success = 0;

    /// <summary>Anything not covered by another code.</summary>
    public const int Failure = 1;

    /// <summary>Invalid input: a bad address, value or option; nothing was sent.</summary>
    public const int InvalidInput = 2;

    /// <summary>The PLC answered with an error end code.</summary>
    public const int EndCode = 3;

    /// <summary>Communication failed: timeout, damaged frames, or the port or connection could not be opened.</summary>
    public const int Communication = 4;

    /// <summary><c>errors</c>: the PLC reports error bits (read, and cleared with <c>--clear</c>).</summary>
    public const int PlcErrors = 5;

    /// <summary>The exit code for an exception that ended a command.</summary>
    public static int For(Exception e) => e switch
    {
        UsageException or ArgumentException or NotSupportedException => InvalidInput,
        HostLinkEndCodeException or FinsEndCodeException => EndCode,
        HostLinkTimeoutException or HostLinkFrameException or HostLinkConnectionException => Communication,
        _ => Failure,
    };
}
