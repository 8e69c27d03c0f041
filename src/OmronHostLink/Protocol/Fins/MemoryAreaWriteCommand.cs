namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0102 MEMORY AREA WRITE: writes elements (2 bytes per word, 1 byte 00/01 per bit) from <see cref="Address"/>.
/// Parameters: area(1) address(2) bit(1) count(2) data.
/// </summary>
/// <remarks>
/// The data must fit in one FA command frame: at most <see cref="MaxDataBytes"/> = 534 bytes (267 words) so that the
/// frame stays within 1,115 characters even with a network header [unverified: the manuals state 1,115 for
/// responses]. Longer writes must be split into several commands.
/// </remarks>
internal sealed class MemoryAreaWriteCommand : FinsCommand
{
    /// <summary>The command code, 0102.</summary>
    public const ushort Code = 0x0102;

    /// <summary>The command's row: 0102 MEMORY AREA WRITE.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "MEMORY AREA WRITE", CommandEffect.Idempotent, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var write = (MemoryAreaWriteCommand)command;
            ushort check = FinsPlcMemory.Check(write.Address, write.Count, write: true);
            if (check == FinsEndCodes.NormalCompletion)
            {
                FinsPlcMemory.Write(plc, write.Address, write.Count, write.Data.Span);
            }

            return FinsReply.Code(check);
        },
        DescribeCommand = static (command, fields) =>
        {
            var write = (MemoryAreaWriteCommand)command;
            FinsAddressField.AddTo(fields, write.Address);
            fields.Field("count", (long)write.Count);
            ReadOnlySpan<byte> data = write.Data.Span;

            // The write data as words (2-byte elements) or bits (bit areas); other element sizes stay in the parameters.
            if (write.Address.IsBit)
            {
                fields.Field("bits", data.ToArray().Select(b => b != 0).ToArray());
            }
            else if (write.Address.ElementSize == 2)
            {
                fields.Field("words", FinsWords.Read(data, data.Length / 2).Select(w => (long)w).ToArray());
            }
        },
    };

    /// <summary>The most data bytes one command carries (<see cref="FinsCommand.MaxParameterLength"/> − 6).</summary>
    public const int MaxDataBytes = MaxParameterLength - 6;

    /// <summary>The most words one command writes.</summary>
    public const int MaxWords = MaxDataBytes / 2;

    private readonly byte[] _data;

    /// <summary>Creates the command from raw element data.</summary>
    /// <param name="address">The first element written.</param>
    /// <param name="data">The element data (copied): a whole number of elements of the area's size.</param>
    /// <exception cref="ArgumentException">The data is not a whole number of elements, or too long for one frame.</exception>
    public MemoryAreaWriteCommand(FinsMemoryAddress address, ReadOnlySpan<byte> data)
    {
        int size = address.ElementSize;
        if (size == 0)
        {
            throw new ArgumentException("The address is not initialised.", nameof(address));
        }

        if (data.Length % size != 0)
        {
            throw new ArgumentException($"{FinsMemoryArea.Describe(address.AreaCode)} elements take {size} bytes; {data.Length} bytes are not a whole number of elements.", nameof(data));
        }

        if (data.Length > MaxDataBytes)
        {
            throw new ArgumentException($"MEMORY AREA WRITE carries at most {MaxDataBytes} data bytes ({MaxWords} words) in one Host Link frame; {data.Length} were given. Split the write.", nameof(data));
        }

        if (size == 1)
        {
            foreach (byte b in data)
            {
                if (b > 1 && FinsMemoryArea.IsBitArea(address.AreaCode))
                {
                    throw new ArgumentException($"Bit data must be 00 or 01; {b:X2} was given.", nameof(data));
                }
            }
        }

        Address = address;
        _data = data.ToArray();
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 6 + _data.Length;

    /// <summary>The first element written.</summary>
    public FinsMemoryAddress Address { get; }

    /// <summary>How many elements are written.</summary>
    public int Count => _data.Length / Address.ElementSize;

    /// <summary>The raw element data.</summary>
    public ReadOnlyMemory<byte> Data => _data;

    /// <summary>A write of words (2 bytes each, most significant first).</summary>
    /// <exception cref="ArgumentException">The area does not hold words, or too many words for one frame.</exception>
    public static MemoryAreaWriteCommand Words(FinsMemoryAddress address, ReadOnlySpan<ushort> words)
    {
        if (address.ElementSize != 2)
        {
            throw new ArgumentException($"Area {address.AreaCode:X2} ({FinsMemoryArea.Describe(address.AreaCode)}) does not hold 2-byte words.", nameof(address));
        }

        if (words.Length > MaxWords)
        {
            throw new ArgumentException($"MEMORY AREA WRITE carries at most {MaxWords} words in one Host Link frame; {words.Length} were given. Split the write.", nameof(words));
        }

        Span<byte> data = stackalloc byte[words.Length * 2];
        FinsWords.Write(words, data);
        return new MemoryAreaWriteCommand(address, data);
    }

    /// <summary>A write of bits (1 byte each, 00 or 01).</summary>
    /// <exception cref="ArgumentException">The area is not bit-addressed, or too many bits for one frame.</exception>
    public static MemoryAreaWriteCommand Bits(FinsMemoryAddress address, ReadOnlySpan<bool> bits)
    {
        if (!address.IsBit || address.ElementSize != 1)
        {
            throw new ArgumentException($"Area {address.AreaCode:X2} ({FinsMemoryArea.Describe(address.AreaCode)}) is not bit-addressed.", nameof(address));
        }

        if (bits.Length > MaxDataBytes)
        {
            throw new ArgumentException($"MEMORY AREA WRITE carries at most {MaxDataBytes} bits in one Host Link frame; {bits.Length} were given. Split the write.", nameof(bits));
        }

        Span<byte> data = stackalloc byte[bits.Length];
        FinsBits.Write(bits, data);
        return new MemoryAreaWriteCommand(address, data);
    }

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        Address.Write(destination);
        FinsBytes.WriteUInt16(destination, 4, (ushort)Count);
        _data.CopyTo(destination.Slice(6));
    }

    internal static MemoryAreaWriteCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 6, MaxParameterLength);
        FinsMemoryAddress address = FinsMemoryAddress.Read(parameters);
        int count = FinsBytes.ReadUInt16(parameters, 4);
        ReadOnlySpan<byte> data = parameters.Slice(6);
        if (data.Length != count * address.ElementSize)
        {
            throw new FinsFormatException(FinsEndCodes.ElementsDataMismatch, $"MEMORY AREA WRITE announces {count} elements of {address.ElementSize} bytes but carries {data.Length} data bytes.");
        }

        if (address.IsBit && address.ElementSize == 1)
        {
            foreach (byte b in data)
            {
                if (b > 1)
                {
                    throw new FinsFormatException(FinsEndCodes.ParameterError, $"Bit data must be 00 or 01; {b:X2} was sent.");
                }
            }
        }

        return new MemoryAreaWriteCommand(address, data);
    }
}
