namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0620 CYCLE TIME READ. Parameter: one byte, 00 = initialise (reset the measurements; no data in the response),
/// 01 = read (average, maximum and minimum cycle time; see <see cref="FinsCycleTime"/>).
/// </summary>
internal sealed class CycleTimeReadCommand : FinsCommand
{
    /// <summary>The command code, 0620.</summary>
    public const ushort Code = FinsCommandCodes.CycleTimeRead;

    /// <summary>Creates the command.</summary>
    /// <param name="initialize">True to reset the measurements (00), false to read them (01).</param>
    public CycleTimeReadCommand(bool initialize = false) => Initialize = initialize;

    /// <inheritdoc/>
    public override ushort CommandCode => Code;

    /// <inheritdoc/>
    public override int ParameterLength => 1;

    /// <summary>True for initialise (00), false for read (01).</summary>
    public bool Initialize { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        destination[0] = Initialize ? (byte)0x00 : (byte)0x01;
    }

    internal static CycleTimeReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 1, 1);
        return parameters[0] switch
        {
            0x00 => new CycleTimeReadCommand(initialize: true),
            0x01 => new CycleTimeReadCommand(initialize: false),
            _ => throw new FinsFormatException(FinsEndCodes.ParameterError, $"CYCLE TIME READ parameter {parameters[0]:X2} is neither 00 (initialise) nor 01 (read)."),
        };
    }
}
