namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// 2301 FORCED SET/RESET: forces bits ON or OFF (or releases them).
/// Parameters: count(2) then [designation(2) area(1) address(2) bit(1)] per bit.
/// </summary>
internal sealed class ForcedSetResetCommand : FinsCommand
{
    /// <summary>The command code, 2301.</summary>
    public const ushort Code = 0x2301;

    /// <summary>The command's row: 2301 FORCED SET/RESET.</summary>
    internal static FinsCommandRow CommandRow { get; } = new(Code, "FORCED SET/RESET", CommandEffect.NotRepeatable, 0) 
    {
        Parse = static p => ParseParameters(p),
        Execute = static (command, plc) => Execute((ForcedSetResetCommand)command, plc),
        DescribeCommand = static (command, fields) => fields.Field("items", ((ForcedSetResetCommand)command).Items.Select(i => FinsAddressField.Of(i.Address, i.Action.ToString())).ToArray()),
    };

    /// <summary>The most bits one command carries: (<see cref="FinsCommand.MaxParameterLength"/> − 2) / 6.</summary>
    public const int MaxItems = (MaxParameterLength - 2) / FinsForcedBit.Length;

    private readonly FinsForcedBit[] _items;

    /// <summary>Creates the command.</summary>
    /// <param name="items">The bits and actions, 1–<see cref="MaxItems"/>.</param>
    /// <exception cref="ArgumentException">No items, too many, or an uninitialised item.</exception>
    public ForcedSetResetCommand(IEnumerable<FinsForcedBit> items)
    {
        _items = Guard.NotNull(items).ToArray();
        if (_items.Length == 0 || _items.Length > MaxItems)
        {
            throw new ArgumentException($"FORCED SET/RESET carries 1-{MaxItems} bits; {_items.Length} were given.", nameof(items));
        }

        foreach (FinsForcedBit item in _items)
        {
            if (!item.Address.IsBit)
            {
                throw new ArgumentException("An item is not initialised.", nameof(items));
            }
        }
    }

    /// <summary>Forces one bit.</summary>
    public ForcedSetResetCommand(FinsForceAction action, FinsMemoryAddress address)
        : this(new[] { new FinsForcedBit(action, address) })
    {
    }

    /// <inheritdoc/>
    public override FinsCommandRow Row => CommandRow;

    /// <inheritdoc/>
    public override int ParameterLength => 2 + (_items.Length * FinsForcedBit.Length);

    /// <summary>The bits and actions, in order.</summary>
    public IReadOnlyList<FinsForcedBit> Items => _items;

    /// <inheritdoc/>
    public override void WriteParameters(Span<byte> destination)
    {
        CheckDestination(destination);
        FinsBytes.WriteUInt16(destination, 0, (ushort)_items.Length);
        for (int i = 0; i < _items.Length; i++)
        {
            _items[i].Write(destination.Slice(2 + (i * FinsForcedBit.Length)));
        }
    }

    internal static ForcedSetResetCommand ParseParameters(ReadOnlySpan<byte> parameters)
    {
        CheckLength(Code, parameters, 2 + FinsForcedBit.Length, 2 + (MaxItems * FinsForcedBit.Length));
        int count = FinsBytes.ReadUInt16(parameters, 0);
        ReadOnlySpan<byte> rest = parameters.Slice(2);
        if (rest.Length % FinsForcedBit.Length != 0)
        {
            throw new FinsFormatException(FinsEndCodes.CommandTooShort, $"FORCED SET/RESET items take {FinsForcedBit.Length} bytes each; the last of {rest.Length} bytes is cut short.");
        }

        if (count != rest.Length / FinsForcedBit.Length)
        {
            throw new FinsFormatException(FinsEndCodes.ElementsDataMismatch, $"FORCED SET/RESET announces {count} bits but carries {rest.Length / FinsForcedBit.Length}.");
        }

        var items = new FinsForcedBit[count];
        for (int i = 0; i < count; i++)
        {
            items[i] = FinsForcedBit.Read(rest.Slice(i * FinsForcedBit.Length));
        }

        return new ForcedSetResetCommand(items);
    }

    /// <summary>Forces or releases each bit, as the PLC does: refused in RUN mode (2206), and all or none.</summary>
    private static FinsReply Execute(ForcedSetResetCommand force, IFinsPlc plc)
    {
        if (plc.Mode == PlcMode.Run)
        {
            return FinsReply.Code(FinsEndCodes.NotExecutableInRunMode);
        }

        var targets = new List<(FinsForceAction Action, FinsPlcMemory.Location Where)>();
        foreach (FinsForcedBit item in force.Items)
        {
            byte code = item.Address.AreaCode;
            if (code is not (FinsMemoryArea.CioBit or FinsMemoryArea.WorkBit or FinsMemoryArea.HoldingBit or FinsMemoryArea.TimerCounterFlag))
            {
                return FinsReply.Code(FinsEndCodes.AreaClassificationMissing);
            }

            if (!FinsPlcMemory.TryLocate(item.Address, 0, out FinsPlcMemory.Location where))
            {
                return FinsReply.Code(FinsEndCodes.AddressRangeError);
            }

            targets.Add((item.Action, where));
        }

        foreach ((FinsForceAction action, FinsPlcMemory.Location where) in targets)
        {
            int bit = where.Flag ? 0 : where.Bit;
            switch (action)
            {
                case FinsForceAction.ForceSet or FinsForceAction.ForceReset:
                    plc.ForceBit(where.Area, where.Word, bit, action == FinsForceAction.ForceSet);
                    break;
                case FinsForceAction.ReleaseToOn or FinsForceAction.ReleaseToOff:
                    plc.ReleaseForced(where.Area, where.Word, bit);
                    FinsPlcMemory.Set(plc, where, action == FinsForceAction.ReleaseToOn);
                    break;
                default:
                    plc.ReleaseForced(where.Area, where.Word, bit);
                    break;
            }
        }

        return FinsReply.Done;
    }
}
