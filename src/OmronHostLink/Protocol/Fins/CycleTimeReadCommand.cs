namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0620 CYCLE TIME READ. Parameter: one byte, 00 = initialise (reset the measurements; no data in the response),
/// 01 = read (average, maximum and minimum cycle time; see <see cref="FinsCycleTime"/>).
/// </summary>
internal sealed class CycleTimeReadCommand : FinsCommand
{
    /// <summary>The command code, 0620.</summary>
    public const ushort Code = 0x0620;

    /// <summary>The command's row: 0620 CYCLE TIME READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "CYCLE TIME READ", CommandEffect.ReadOnly, FinsCycleTime.Length) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (_, _) =>
        {
            // 1.0 ms average, 1.5 ms maximum, 0.8 ms minimum, in 0.1 ms units.
            var data = new byte[FinsCycleTime.Length];
            new FinsCycleTime(10, 15, 8).Write(data);
            return FinsReply.Ok(data);
        },
        DescribeCommand = static (command, fields) => fields.Field("initialize", ((CycleTimeReadCommand)command).Initialize),
    };

    /// <summary>Creates the command.</summary>
    /// <param name="initialize">True to reset the measurements (00), false to read them (01).</param>
    public CycleTimeReadCommand(bool initialize = false) => Initialize = initialize;

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 1;

    /// <summary>True for initialise (00), false for read (01).</summary>
    public bool Initialize { get; }

    /// <summary>Reading is repeatable; initialising restarts the measurement, so it is not repeated.</summary>
    public override CommandEffect Effect => Initialize ? CommandEffect.NotRepeatable : CommandEffect.ReadOnly;

    /// <summary>Initialising is answered without data.</summary>
    public override int MaxResponseDataLength => Initialize ? 0 : FinsCycleTime.Length;

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
