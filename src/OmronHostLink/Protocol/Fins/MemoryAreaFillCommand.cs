namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0103 MEMORY AREA FILL: writes one word value to <see cref="Count"/> consecutive words.
/// Parameters: area(1) address(2) bit(1) count(2) value(2). Word areas only.
/// </summary>
internal sealed class MemoryAreaFillCommand : FinsCommand
{
    /// <summary>The command code, 0103.</summary>
    public const ushort Code = 0x0103;

    /// <summary>The command's row: 0103 MEMORY AREA FILL.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "MEMORY AREA FILL", CommandEffect.Idempotent, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var fill = (MemoryAreaFillCommand)command;
            ushort check = FinsPlcMemory.Check(fill.Address, fill.Count, write: true);
            if (check != FinsEndCodes.NormalCompletion)
            {
                return FinsReply.Code(check);
            }

            int size = fill.Address.ElementSize;
            var bytes = new byte[fill.Count * size];
            for (int i = 0; i < fill.Count; i++)
            {
                if (size == 2)
                {
                    FinsBytes.WriteUInt16(bytes, i * 2, fill.Value);
                }
                else
                {
                    bytes[i] = fill.Value != 0 ? (byte)1 : (byte)0;
                }
            }

            FinsPlcMemory.Write(plc, fill.Address, fill.Count, bytes);
            return FinsReply.Done;
        },
        DescribeCommand = static (command, fields) =>
        {
            var fill = (MemoryAreaFillCommand)command;
            FinsAddressField.AddTo(fields, fill.Address);
            fields.Field("count", (long)fill.Count);
            fields.Field("value", (long)fill.Value);
        },
    };

    /// <summary>Creates the command.</summary>
    /// <param name="address">The first word (a 2-byte word area).</param>
    /// <param name="count">Words to fill, 0–65535.</param>
    /// <param name="value">The value written to each word.</param>
    /// <exception cref="ArgumentException">The area does not hold 2-byte words.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The count is out of range.</exception>
    public MemoryAreaFillCommand(FinsMemoryAddress address, int count, ushort value)
    {
        if (address.ElementSize != 2)
        {
            throw new ArgumentException($"MEMORY AREA FILL writes words; area {address.AreaCode:X2} ({FinsMemoryArea.Describe(address.AreaCode)}) does not hold 2-byte words.", nameof(address));
        }

        Guard.InRange(count, 0, ushort.MaxValue);
        Address = address;
        Count = count;
        Value = value;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 8;

    /// <summary>The first word filled.</summary>
    public FinsMemoryAddress Address { get; }

    /// <summary>How many words are filled.</summary>
    public int Count { get; }

    /// <summary>The value written.</summary>
    public ushort Value { get; }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        Address.Write(destination);
        FinsBytes.WriteUInt16(destination, 4, (ushort)Count);
        FinsBytes.WriteUInt16(destination, 6, Value);
    }

    internal static MemoryAreaFillCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 8, 8);
        FinsMemoryAddress address = FinsMemoryAddress.Read(parameters);
        if (address.ElementSize != 2)
        {
            throw new FinsFormatException(FinsEndCodes.AreaClassificationMissing, $"MEMORY AREA FILL cannot fill area {address.AreaCode:X2} ({FinsMemoryArea.Describe(address.AreaCode)}).");
        }

        return new MemoryAreaFillCommand(address, FinsBytes.ReadUInt16(parameters, 4), FinsBytes.ReadUInt16(parameters, 6));
    }
}
