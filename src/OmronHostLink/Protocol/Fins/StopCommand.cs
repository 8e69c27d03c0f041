using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>0402 STOP: puts the CPU Unit into PROGRAM mode. Parameter (optional): program number(2, <c>FFFF</c>).</summary>
internal sealed class StopCommand : FinsCommand
{
    /// <summary>The command code, 0402.</summary>
    public const ushort Code = 0x0402;

    /// <summary>The command's row: 0402 STOP.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "STOP", CommandEffect.NotRepeatable, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (_, plc) =>
        {
            plc.Mode = PlcMode.Program;
            return FinsReply.Done;
        },
        DescribeCommand = static (command, fields) => fields.Field("programNumber", ((StopCommand)command).ProgramNumber is { } program ? program.ToString("X4", CultureInfo.InvariantCulture) : null),
    };

    /// <summary>Stops with program number FFFF.</summary>
    public StopCommand()
        : this(RunCommand.AnyProgram)
    {
    }

    /// <summary>Stops with the given program number, or with no parameter when it is null.</summary>
    public StopCommand(ushort? programNumber) => ProgramNumber = programNumber;

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => ProgramNumber is null ? 0 : 2;

    /// <summary>The program number sent, if any.</summary>
    public ushort? ProgramNumber { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        if (ProgramNumber is ushort program)
        {
            FinsBytes.WriteUInt16(destination, 0, program);
        }
    }

    internal static StopCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 2);
        if (parameters.Length == 1)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooShort, "STOP's program number takes 2 bytes; 1 was sent.");
        }

        return new StopCommand(parameters.Length == 2 ? FinsBytes.ReadUInt16(parameters, 0) : null);
    }
}
