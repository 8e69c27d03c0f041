namespace OmronHostLink;

/// <summary>The PLC did not answer (or stopped answering in the middle of a frame) within the deadline.</summary>
public sealed class HostLinkTimeoutException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    public HostLinkTimeoutException(string message, TimeSpan timeout)
        : base(message)
    {
        Timeout = timeout;
    }

    /// <summary>Creates the exception with the failure it restates.</summary>
    internal HostLinkTimeoutException(string message, TimeSpan timeout, Exception? innerException)
        : base(message, innerException)
    {
        Timeout = timeout;
    }

    /// <summary>The deadline that passed.</summary>
    public TimeSpan Timeout { get; }

    /// <inheritdoc/>
    /// <remarks>Always true: the next attempt may be answered.</remarks>
    public override bool IsTransient => true;
}
