using System.Globalization;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>The PLC answered a FINS command with an error response code.</summary>
public sealed class FinsEndCodeException : EndCodeException
{
    /// <summary>Creates the exception.</summary>
    public FinsEndCodeException(FinsEndCode endCode, ushort command, int unit)
        : base($"Unit {unit:D2} answered FINS {command:X4} with response code {endCode}: {endCode.Meaning}.", unit)
    {
        EndCode = endCode;
        Command = command;
    }

    /// <summary>The response code with its flags.</summary>
    public FinsEndCode EndCode { get; }

    /// <summary>The FINS command code (MRC × 256 + SRC) that failed.</summary>
    public ushort Command { get; }

    /// <inheritdoc/>
    /// <remarks>True for response codes that report a busy or timed-out network (<see cref="FinsEndCode.IsTransient"/>).</remarks>
    public override bool IsTransient => EndCode.IsTransient;

    /// <inheritdoc/>
    /// <remarks>False: FINS response codes report on the FINS network and the PLC, not on the Host Link line.</remarks>
    internal override bool ReportsLineDamage => false;

    /// <inheritdoc/>
    /// <remarks><c>fins_</c> and the response code without its relay and CPU-error flags (<c>fins_0401</c>).</remarks>
    internal override string ErrorType => "fins_" + EndCode.Code.ToString("X4", CultureInfo.InvariantCulture);

    /// <inheritdoc/>
    /// <remarks>Always <c>00</c>: FINS answers travel inside a Host Link frame whose own end code was normal completion.</remarks>
    internal override string FrameEndCode => "00";

    /// <inheritdoc/>
    internal override string? CarriedEndCode => EndCode.Raw.ToString("X4", CultureInfo.InvariantCulture);
}
