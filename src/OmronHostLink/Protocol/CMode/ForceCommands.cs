namespace OmronHostLink.Protocol.CMode;

/// <summary>KS (FORCED SET) or KR (FORCED RESET) of one bit.</summary>
internal sealed class ForceBitCommand : CModeCommand
{
    /// <summary>Creates the command.</summary>
    public ForceBitCommand(bool set, ForceArea area, int word, int bit)
    {
        ForceAreaInfo.Check(area, word, bit);
        Set = set;
        Area = area;
        Word = word;
        Bit = bit;
    }

    /// <summary>True for KS (set), false for KR (reset).</summary>
    public bool Set { get; }

    /// <summary>The area.</summary>
    public ForceArea Area { get; }

    /// <summary>The word (or timer/counter number).</summary>
    public int Word { get; }

    /// <summary>The bit (00 for timers and counters).</summary>
    public int Bit { get; }

    /// <inheritdoc/>
    public override string Header => Set ? CModeHeaders.ForcedSet : CModeHeaders.ForcedReset;

    /// <inheritdoc/>
    public override int TextLength => 10;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
        string name = ForceAreaInfo.Name(Area);
        for (int i = 0; i < 4; i++)
        {
            destination[i] = (byte)name[i];
        }

        HexAscii.WriteDecimal(Word, destination.Slice(4, 4));
        HexAscii.WriteDecimal(Bit, destination.Slice(8, 2));
    }
}

/// <summary>What FK does to one bit.</summary>
internal enum ForceAction
{
    /// <summary>0: leave the bit as it is.</summary>
    None = 0,

    /// <summary>2: reset the bit.</summary>
    Reset = 2,

    /// <summary>3: set the bit.</summary>
    Set = 3,

    /// <summary>4: force the bit off.</summary>
    ForcedReset = 4,

    /// <summary>5: force the bit on.</summary>
    ForcedSet = 5,

    /// <summary>8: cancel the bit's forced state.</summary>
    Cancel = 8,
}

/// <summary>FK: MULTIPLE FORCED SET/RESET of the 16 bits of one word (actions listed from bit 15 down to bit 0).</summary>
internal sealed class MultipleForceCommand : CModeCommand
{
    private readonly ForceAction[] _actions;

    /// <summary>Creates the command.</summary>
    /// <param name="area">The area.</param>
    /// <param name="word">The word (or timer/counter number).</param>
    /// <param name="actionsBit15To0">Sixteen actions, the first for bit 15, the last for bit 0.</param>
    public MultipleForceCommand(ForceArea area, int word, IReadOnlyList<ForceAction> actionsBit15To0)
    {
        Guard.NotNull(actionsBit15To0);
        ForceAreaInfo.Check(area, word, 0);
        if (actionsBit15To0.Count != 16)
        {
            throw new ArgumentException($"FK takes 16 actions (bit 15 to bit 0); {actionsBit15To0.Count} were given.", nameof(actionsBit15To0));
        }

        _actions = new ForceAction[16];
        for (int i = 0; i < 16; i++)
        {
            ForceAction a = actionsBit15To0[i];
            if (a is not (ForceAction.None or ForceAction.Reset or ForceAction.Set or ForceAction.ForcedReset or ForceAction.ForcedSet or ForceAction.Cancel))
            {
                throw new ArgumentOutOfRangeException(nameof(actionsBit15To0), a, $"Unknown force action for bit {15 - i}.");
            }

            _actions[i] = a;
        }

        Area = area;
        Word = word;
    }

    /// <summary>The area.</summary>
    public ForceArea Area { get; }

    /// <summary>The word.</summary>
    public int Word { get; }

    /// <summary>The actions, bit 15 first.</summary>
    public IReadOnlyList<ForceAction> Actions => _actions;

    /// <inheritdoc/>
    public override string Header => CModeHeaders.MultipleForcedSetReset;

    /// <inheritdoc/>
    public override int TextLength => 24;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
        string name = ForceAreaInfo.Name(Area);
        for (int i = 0; i < 4; i++)
        {
            destination[i] = (byte)name[i];
        }

        HexAscii.WriteDecimal(Word, destination.Slice(4, 4));
        for (int i = 0; i < 16; i++)
        {
            destination[8 + i] = (byte)('0' + (int)_actions[i]);
        }
    }
}
