using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0401 RUN: puts the CPU Unit into MONITOR or RUN mode. Parameters (all optional): program number(2, <c>FFFF</c>)
/// then mode(1: 02 MONITOR, 04 RUN). The mode can only be sent after a program number.
/// </summary>
internal sealed class RunCommand : FinsCommand
{
    /// <summary>The command code, 0401.</summary>
    public const ushort Code = 0x0401;

    /// <summary>The command's row: 0401 RUN.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "RUN", CommandEffect.NotRepeatable, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            // [unverified] With no mode given the CPU Unit goes to MONITOR mode.
            plc.Mode = ((RunCommand)command).Mode == FinsCpuMode.Run ? PlcMode.Run : PlcMode.Monitor;
            return FinsReply.Done;
        },
        DescribeCommand = static (command, fields) =>
        {
            var run = (RunCommand)command;
            fields.Field("programNumber", run.ProgramNumber is { } program ? program.ToString("X4", CultureInfo.InvariantCulture) : null);
            fields.Field("mode", run.Mode is { } mode ? FinsCpuStatus.ModeName(mode) : null);
        },
    };

    /// <summary>The program number CS/CJ CPU Units expect.</summary>
    public const ushort AnyProgram = 0xFFFF;

    /// <summary>Switches to <paramref name="mode"/> with program number FFFF.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The mode is not MONITOR or RUN.</exception>
    public RunCommand(FinsCpuMode mode)
        : this(AnyProgram, mode)
    {
    }

    /// <summary>Creates the command with any combination of its optional parameters.</summary>
    /// <param name="programNumber">The program number (normally <see cref="AnyProgram"/>), or null to send no parameters.</param>
    /// <param name="mode">MONITOR or RUN, or null to let the PLC choose its default.</param>
    /// <exception cref="ArgumentException">A mode without a program number.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The mode is not MONITOR or RUN.</exception>
    public RunCommand(ushort? programNumber, FinsCpuMode? mode)
    {
        if (mode is not null && programNumber is null)
        {
            throw new ArgumentException("RUN sends the mode after the program number; give a program number (FFFF) with a mode.", nameof(programNumber));
        }

        if (mode is not null and not FinsCpuMode.Monitor and not FinsCpuMode.Run)
        {
            throw new ArgumentOutOfRangeException(nameof(mode), mode, "RUN switches to MONITOR (02) or RUN (04); use STOP for PROGRAM mode.");
        }

        ProgramNumber = programNumber;
        Mode = mode;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => ProgramNumber is null ? 0 : Mode is null ? 2 : 3;

    /// <summary>The program number sent, if any.</summary>
    public ushort? ProgramNumber { get; }

    /// <summary>The mode sent, if any.</summary>
    public FinsCpuMode? Mode { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        if (ProgramNumber is ushort program)
        {
            FinsBytes.WriteUInt16(destination, 0, program);
        }

        if (Mode is FinsCpuMode mode)
        {
            destination[2] = (byte)mode;
        }
    }

    internal static RunCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 0, 3);
        if (parameters.Length == 1)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooShort, "RUN's program number takes 2 bytes; 1 was sent.");
        }

        ushort? program = parameters.Length >= 2 ? FinsBytes.ReadUInt16(parameters, 0) : null;
        FinsCpuMode? mode = null;
        if (parameters.Length == 3)
        {
            mode = (FinsCpuMode)parameters[2];
            if (mode is not FinsCpuMode.Monitor and not FinsCpuMode.Run)
            {
                throw new FinsFormatException(FinsEndCodes.ParameterError, $"RUN mode {parameters[2]:X2} is neither 02 (MONITOR) nor 04 (RUN).");
            }
        }

        return new RunCommand(program, mode);
    }
}
