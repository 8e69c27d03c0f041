namespace OmronHostLink;

/// <summary>
/// The PLC answered with an error code: the exchange was complete, nothing was returned, and the link is still in step
/// with the PLC. The base of <see cref="HostLinkEndCodeException"/> (C-mode end codes) and
/// <see cref="FinsEndCodeException"/> (FINS response codes), so that one <c>catch</c> takes either.
/// </summary>
public abstract class EndCodeException : HostLinkException
{
    private protected EndCodeException(string message, int unit)
        : base(message)
    {
        Unit = unit;
    }

    /// <summary>The Host Link unit number that answered.</summary>
    public int Unit { get; }

    /// <summary>
    /// Whether the code reports a command frame that reached the PLC damaged: the link repeats such a command as it
    /// repeats one that went unanswered.
    /// </summary>
    internal abstract bool ReportsLineDamage { get; }

    /// <summary>A short, low-cardinality name for the code, for grouping failures (<c>error.type</c>).</summary>
    internal abstract string ErrorType { get; }

    /// <summary>The two-character end code of the Host Link frame that carried the answer.</summary>
    internal abstract string FrameEndCode { get; }

    /// <summary>The code of the command carried inside the Host Link frame (a FINS response code), where there is one.</summary>
    internal virtual string? CarriedEndCode => null;
}
