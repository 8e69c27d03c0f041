using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>The PLC answered a FINS command with an error response code.</summary>
public sealed class FinsEndCodeException : HostLinkException
{
    /// <summary>Creates the exception.</summary>
    public FinsEndCodeException(FinsEndCode endCode, ushort command, int unit)
        : base($"Unit {unit:D2} answered FINS {command:X4} with response code {endCode}: {endCode.Meaning}.")
    {
        EndCode = endCode;
        Command = command;
        Unit = unit;
    }

    /// <summary>The response code with its flags.</summary>
    public FinsEndCode EndCode { get; }

    /// <summary>The FINS command code (MRC × 256 + SRC) that failed.</summary>
    public ushort Command { get; }

    /// <summary>The Host Link unit number that answered.</summary>
    public int Unit { get; }

    /// <inheritdoc/>
    /// <remarks>True for response codes that report a busy or timed-out network (<see cref="FinsEndCode.IsTransient"/>).</remarks>
    public override bool IsTransient => EndCode.IsTransient;
}
