namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0105 MEMORY AREA TRANSFER: copies <see cref="Count"/> words inside the PLC.
/// Parameters: source area(1) address(2) bit(1), destination area(1) address(2) bit(1), count(2). Word areas only.
/// </summary>
internal sealed class MemoryAreaTransferCommand : FinsCommand
{
    /// <summary>The command code, 0105.</summary>
    public const ushort Code = 0x0105;

    /// <summary>The command's row: 0105 MEMORY AREA TRANSFER.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "MEMORY AREA TRANSFER", CommandEffect.Idempotent, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var transfer = (MemoryAreaTransferCommand)command;
            if (FinsMemoryArea.ElementSize(transfer.Source.AreaCode) != 2 || FinsMemoryArea.ElementSize(transfer.Destination.AreaCode) != 2)
            {
                return FinsReply.Code(FinsEndCodes.AreaClassificationMissing);
            }

            ushort check = FinsPlcMemory.Check(transfer.Source, transfer.Count, write: false);
            check = check != FinsEndCodes.NormalCompletion ? check : FinsPlcMemory.Check(transfer.Destination, transfer.Count, write: true);
            if (check == FinsEndCodes.NormalCompletion && transfer.Count > 0)
            {
                FinsPlcMemory.Write(plc, transfer.Destination, transfer.Count, FinsPlcMemory.Read(plc, transfer.Source, transfer.Count));
            }

            return FinsReply.Code(check);
        },
        DescribeCommand = static (command, fields) =>
        {
            var transfer = (MemoryAreaTransferCommand)command;
            fields.Field("source", FinsAddressField.Of(transfer.Source));
            fields.Field("destination", FinsAddressField.Of(transfer.Destination));
            fields.Field("count", (long)transfer.Count);
        },
    };

    /// <summary>Creates the command.</summary>
    /// <param name="source">The first word copied (a 2-byte word area).</param>
    /// <param name="destination">The first word written (a 2-byte word area).</param>
    /// <param name="count">Words copied, 0–65535.</param>
    /// <exception cref="ArgumentException">An area does not hold 2-byte words.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The count is out of range.</exception>
    public MemoryAreaTransferCommand(FinsMemoryAddress source, FinsMemoryAddress destination, int count)
    {
        if (source.ElementSize != 2)
        {
            throw new ArgumentException($"MEMORY AREA TRANSFER copies words; area {source.AreaCode:X2} does not hold 2-byte words.", nameof(source));
        }

        if (destination.ElementSize != 2)
        {
            throw new ArgumentException($"MEMORY AREA TRANSFER copies words; area {destination.AreaCode:X2} does not hold 2-byte words.", nameof(destination));
        }

        Guard.InRange(count, 0, ushort.MaxValue);
        Source = source;
        Destination = destination;
        Count = count;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 10;

    /// <summary>The first word copied.</summary>
    public FinsMemoryAddress Source { get; }

    /// <summary>The first word written.</summary>
    public FinsMemoryAddress Destination { get; }

    /// <summary>How many words are copied.</summary>
    public int Count { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        Source.Write(destination);
        Destination.Write(destination.Slice(4));
        FinsBytes.WriteUInt16(destination, 8, (ushort)Count);
    }

    internal static MemoryAreaTransferCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 10, 10);
        FinsMemoryAddress source = FinsMemoryAddress.Read(parameters);
        FinsMemoryAddress destination = FinsMemoryAddress.Read(parameters.Slice(4));
        if (source.ElementSize != 2 || destination.ElementSize != 2)
        {
            throw new FinsFormatException(FinsEndCodes.AreaClassificationMissing, "MEMORY AREA TRANSFER copies 2-byte words only.");
        }

        return new MemoryAreaTransferCommand(source, destination, FinsBytes.ReadUInt16(parameters, 8));
    }
}
