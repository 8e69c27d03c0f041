namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0101 MEMORY AREA READ: <see cref="Count"/> consecutive elements (words or bits) from <see cref="Address"/>.
/// Parameters: area(1) address(2) bit(1) count(2). The response carries 2 bytes per word, 1 byte (00/01) per bit.
/// </summary>
/// <remarks>
/// Over Host Link the response data is limited to 1,076 characters, i.e. <see cref="MaxResponseDataBytes"/> = 538
/// bytes (W342 p69): at most <see cref="MaxWords"/> = 269 words or 538 bits in one command; a longer read must be
/// split into several commands. A count of 0 is legal and returns no data (W342 p194).
/// </remarks>
internal sealed class MemoryAreaReadCommand : FinsCommand
{
    /// <summary>The command code, 0101.</summary>
    public const ushort Code = 0x0101;

    /// <summary>The command's row: 0101 MEMORY AREA READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "MEMORY AREA READ", CommandEffect.ReadOnly, MaxResponseDataBytes) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var read = (MemoryAreaReadCommand)command;
            ushort check = FinsPlcMemory.Check(read.Address, read.Count, write: false);
            return check == FinsEndCodes.NormalCompletion ? FinsReply.Ok(FinsPlcMemory.Read(plc, read.Address, read.Count)) : FinsReply.Code(check);
        },
        DescribeCommand = static (command, fields) =>
        {
            var read = (MemoryAreaReadCommand)command;
            FinsAddressField.AddTo(fields, read.Address);
            fields.Field("count", (long)read.Count);
        },
    };

    /// <summary>The most response data bytes one FA response holds (1,076 characters).</summary>
    public const int MaxResponseDataBytes = 538;

    /// <summary>The most words one command reads over Host Link (538 bytes / 2).</summary>
    public const int MaxWords = MaxResponseDataBytes / FinsMemoryArea.WordSize;

    /// <summary>The most bits one command reads over Host Link (1 byte each).</summary>
    public const int MaxBits = MaxResponseDataBytes / FinsMemoryArea.BitSize;

    /// <summary>Parameter bytes: the first element's address and the count (2).</summary>
    public const int ParametersLength = FinsMemoryAddress.Length + 2;

    /// <summary>Creates the command.</summary>
    /// <param name="address">The first element.</param>
    /// <param name="count">Elements to read: 0–269 words (0–538 bits; fewer for 4-byte elements).</param>
    /// <exception cref="ArgumentOutOfRangeException">The count is negative or the response would not fit in one frame.</exception>
    public MemoryAreaReadCommand(FinsMemoryAddress address, int count)
    {
        if (address.ElementSize == 0)
        {
            throw new ArgumentException("The address is not initialised.", nameof(address));
        }

        int max = MaxCount(address.AreaCode);
        if (count < 0 || count > max)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"MEMORY AREA READ of {FinsMemoryArea.Describe(address.AreaCode)} reads 0-{max} elements in one Host Link command; {count} were asked. Split the read.");
        }

        Address = address;
        Count = count;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => ParametersLength;

    /// <summary>The first element read.</summary>
    public FinsMemoryAddress Address { get; }

    /// <summary>How many elements are read.</summary>
    public int Count { get; }

    /// <summary>The exact number of data bytes the response to this command carries.</summary>
    public int ResponseDataLength => Count * Address.ElementSize;

    /// <inheritdoc/>
    public override int MaxResponseDataLength => ResponseDataLength;

    /// <summary>The most elements of area <paramref name="areaCode"/> one command reads.</summary>
    public static int MaxCount(byte areaCode)
    {
        int size = FinsMemoryArea.ElementSize(areaCode);
        return size == 0 ? 0 : MaxResponseDataBytes / size;
    }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        Address.Write(destination);
        FinsBytes.WriteUInt16(destination, 4, (ushort)Count);
    }

    internal static MemoryAreaReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, ParametersLength, ParametersLength);
        FinsMemoryAddress address = FinsMemoryAddress.Read(parameters);
        int count = FinsBytes.ReadUInt16(parameters, 4);
        if (count > MaxCount(address.AreaCode))
        {
            throw new FinsFormatException(FinsEndCodes.ResponseTooLong, $"Reading {count} elements of {FinsMemoryArea.Describe(address.AreaCode)} needs a response longer than a Host Link frame holds.");
        }

        return new MemoryAreaReadCommand(address, count);
    }
}
