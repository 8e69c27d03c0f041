namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 0104 MULTIPLE MEMORY AREA READ: reads one element at each of several addresses.
/// Parameters: [area(1) address(2) bit(1)] repeated. The response repeats [area(1) data(element size)].
/// </summary>
internal sealed class MultipleMemoryAreaReadCommand : FinsCommand
{
    /// <summary>The command code, 0104.</summary>
    public const ushort Code = 0x0104;

    /// <summary>The command's row: 0104 MULTIPLE MEMORY AREA READ.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "MULTIPLE MEMORY AREA READ", CommandEffect.ReadOnly, MemoryAreaReadCommand.MaxResponseDataBytes) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) =>
        {
            var data = new List<byte>();
            foreach (FinsMemoryAddress item in ((MultipleMemoryAreaReadCommand)command).Items)
            {
                ushort check = FinsPlcMemory.Check(item, 1, write: false);
                if (check != FinsEndCodes.NormalCompletion)
                {
                    return FinsReply.Code(check);
                }

                data.Add(item.AreaCode);
                data.AddRange(FinsPlcMemory.Read(plc, item, 1));
            }

            return FinsReply.Ok(data.ToArray());
        },
        DescribeCommand = static (command, fields) => fields.Field("items", ((MultipleMemoryAreaReadCommand)command).Items.Select(a => FinsAddressField.Of(a)).ToArray()),
    };

    /// <summary>The most items one command carries (<see cref="FinsCommand.MaxParameterLength"/> / 4).</summary>
    public const int MaxItems = MaxParameterLength / FinsMemoryAddress.Length;

    private readonly FinsMemoryAddress[] _items;

    /// <summary>Bytes an item of <paramref name="elementSize"/> bytes takes in the answer: its area code, then the element.</summary>
    public static int ResponseItemLength(int elementSize) => 1 + elementSize;

    /// <summary>Creates the command.</summary>
    /// <param name="items">The addresses read, 1–<see cref="MaxItems"/>, in order.</param>
    /// <exception cref="ArgumentException">No items, too many, or a response that would not fit in one frame.</exception>
    public MultipleMemoryAreaReadCommand(IEnumerable<FinsMemoryAddress> items)
    {
        _items = Guard.NotNull(items).ToArray();
        if (_items.Length == 0 || _items.Length > MaxItems)
        {
            throw new ArgumentException($"MULTIPLE MEMORY AREA READ reads 1-{MaxItems} items; {_items.Length} were given.", nameof(items));
        }

        int response = 0;
        foreach (FinsMemoryAddress item in _items)
        {
            if (item.ElementSize == 0)
            {
                throw new ArgumentException("An item address is not initialised.", nameof(items));
            }

            response += ResponseItemLength(item.ElementSize);
        }

        if (response > MemoryAreaReadCommand.MaxResponseDataBytes)
        {
            throw new ArgumentException($"The response to these {_items.Length} items would carry {response} bytes; at most {MemoryAreaReadCommand.MaxResponseDataBytes} fit in a Host Link frame. Split the read.", nameof(items));
        }

        ResponseDataLength = response;
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => _items.Length * FinsMemoryAddress.Length;

    /// <summary>The addresses read, in order.</summary>
    public IReadOnlyList<FinsMemoryAddress> Items => _items;

    /// <summary>The exact number of data bytes the response carries (area code + element per item).</summary>
    public int ResponseDataLength { get; }

    /// <inheritdoc/>
    public override int MaxResponseDataLength => ResponseDataLength;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        for (int i = 0; i < _items.Length; i++)
        {
            _items[i].Write(destination.Slice(i * FinsMemoryAddress.Length));
        }
    }

    internal static MultipleMemoryAreaReadCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, FinsMemoryAddress.Length, MaxItems * FinsMemoryAddress.Length);
        if (parameters.Length % FinsMemoryAddress.Length != 0)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooShort, $"MULTIPLE MEMORY AREA READ items take 4 bytes each; the last of {parameters.Length} bytes is cut short.");
        }

        var items = new FinsMemoryAddress[parameters.Length / FinsMemoryAddress.Length];
        int response = 0;
        for (int i = 0; i < items.Length; i++)
        {
            items[i] = FinsMemoryAddress.Read(parameters.Slice(i * FinsMemoryAddress.Length));
            response += ResponseItemLength(items[i].ElementSize);
        }

        if (response > MemoryAreaReadCommand.MaxResponseDataBytes)
        {
            throw new FinsFormatException(FinsEndCodes.ResponseTooLong, $"The response to {items.Length} items would need {response} bytes, more than a Host Link frame holds.");
        }

        return new MultipleMemoryAreaReadCommand(items);
    }
}
