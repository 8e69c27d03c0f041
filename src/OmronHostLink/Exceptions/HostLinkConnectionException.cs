namespace OmronHostLink;

/// <summary>The link to the PLC could not be opened, or was lost (port gone, gateway closed the connection).</summary>
public sealed class HostLinkConnectionException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    public HostLinkConnectionException(string message, Exception? innerException = null)
        : base(message, innerException)
    {
    }

    /// <inheritdoc/>
    /// <remarks>Always true: the next call opens the link again.</remarks>
    public override bool IsTransient => true;
}
