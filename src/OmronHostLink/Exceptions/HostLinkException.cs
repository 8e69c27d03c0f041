namespace OmronHostLink;

/// <summary>The base of every failure this library reports about a PLC exchange.</summary>
public class HostLinkException : Exception
{
    /// <summary>Creates the exception.</summary>
    public HostLinkException(string message)
        : base(message)
    {
    }

    /// <summary>Creates the exception with its cause.</summary>
    public HostLinkException(string message, Exception? innerException)
        : base(message, innerException)
    {
    }

    /// <summary>
    /// Whether the same operation may succeed when tried again: true for a timeout, a damaged or unexpected frame, a
    /// lost or unavailable link, and PLC end codes that report damage on the line or a busy network (C-mode 13, A3 and
    /// their kin; FINS 0102–0104, 0204, 0205). False for a failure that repeats the same way every time: a refused
    /// address, the wrong operating mode, an unsupported command. A write that failed transiently may still have been
    /// executed; whether to repeat it is the caller's decision.
    /// </summary>
    public virtual bool IsTransient => false;
}
