namespace OmronHostLink.Gateway.Configuration;

/// <summary>The gateway's exit codes besides 0.</summary>
internal static class ExitCodes
{
    /// <summary>The configuration is not valid: a service manager should not restart the gateway on it.</summary>
    public const int InvalidConfiguration = 2;
}
