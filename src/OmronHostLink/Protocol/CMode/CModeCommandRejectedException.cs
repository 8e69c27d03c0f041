namespace OmronHostLink.Protocol.CMode;

/// <summary>A received C-mode command that a PLC refuses; <see cref="EndCode"/> is what it answers.</summary>
internal sealed class CModeCommandRejectedException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    public CModeCommandRejectedException(EndCode endCode, string message)
        : base(message)
    {
        EndCode = endCode;
    }

    /// <summary>The end code a PLC answers the command with.</summary>
    public EndCode EndCode { get; }
}
