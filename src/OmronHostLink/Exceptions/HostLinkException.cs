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
}
