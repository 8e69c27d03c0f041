namespace OmronHostLink.Cli;

/// <summary>The command line asks for something invalid; nothing has been sent. Exit code 2.</summary>
internal sealed class UsageException : Exception
{
    public UsageException(string message)
        : base(message)
    {
    }

    public UsageException(string message, Exception innerException)
        : base(message, innerException)
    {
    }
}
