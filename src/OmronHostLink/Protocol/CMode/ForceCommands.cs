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
    public override CModeCommandRow Row => Set ? SetRow : ResetRow;

    /// <summary>KS: FORCED SET.</summary>
    internal static CModeCommandRow SetRow { get; } = CreateRow(set: true);

    /// <summary>KR: FORCED RESET.</summary>
    internal static CModeCommandRow ResetRow { get; } = CreateRow(set: false);

    private static CModeCommandRow CreateRow(bool set)
        => new(set ? "KS" : "KR", set ? "FORCED SET" : "FORCED RESET", CommandEffect.NotRepeatable, CModeResponse.EndCodeLength)
        {
            Parse = text => Parse(set, text),
            Execute = static (command, plc, _) =>
            {
                var force = (ForceBitCommand)command;
                if (plc.Mode == PlcMode.Run)
                {
                    return CModeReply.EndCodeOnly(EndCode.NotExecutableInRunMode);
                }

                (PlcArea area, int word) = CModeAddressing.Locate(force.Area, force.Word);
                plc.ForceBit(area, word, force.Bit, force.Set);
                return CModeReply.EndCodeOnly(EndCode.NormalCompletion);
            },
            DescribeCommand = static (command, fields) =>
            {
                var k = (ForceBitCommand)command;
                fields.Field("action", k.Set ? "set" : "reset");
                fields.Field("area", ForceAreaInfo.Name(k.Area).Trim());
                fields.Field("word", (long)k.Word);
                fields.Field("bit", (long)k.Bit);
            },
        };

    private static ForceBitCommand Parse(bool set, ReadOnlySpan<byte> text)
    {
        CModeCommandParser.ExpectLength(text, 10, (set ? SetRow : ResetRow).Header);
        if (!ForceAreaInfo.TryParse(text.Slice(0, 4), out ForceArea area)
            || !HexAscii.TryParseDecimal(text.Slice(4, 4), out int word)
            || !HexAscii.TryParseDecimal(text.Slice(8, 2), out int bit))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "Area name, word or bit is not valid.");
        }

        return CModeCommandParser.Checked(() => new ForceBitCommand(set, area, word, bit));
    }

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
    public override CModeCommandRow Row => CommandRow;

    /// <summary>FK: MULTIPLE FORCED SET/RESET.</summary>
    internal static CModeCommandRow CommandRow { get; } = new("FK", "MULTIPLE FORCED SET/RESET", CommandEffect.NotRepeatable, CModeResponse.EndCodeLength)
    {
        Parse = Parse,
        Execute = static (command, plc, _) =>
        {
            if (plc.Mode == PlcMode.Run)
            {
                return CModeReply.EndCodeOnly(EndCode.NotExecutableInRunMode);
            }

            Execute((MultipleForceCommand)command, plc);
            return CModeReply.EndCodeOnly(EndCode.NormalCompletion);
        },
        DescribeCommand = static (command, fields) =>
        {
            var fk = (MultipleForceCommand)command;
            fields.Field("area", ForceAreaInfo.Name(fk.Area).Trim());
            fields.Field("word", (long)fk.Word);
            fields.Field("actionsBit15To0", fk.Actions.Select(a => a.ToString()).ToArray());
        },
    };

    private static MultipleForceCommand Parse(ReadOnlySpan<byte> text)
    {
        CModeCommandParser.ExpectLength(text, 24, CommandRow.Header);
        if (!ForceAreaInfo.TryParse(text.Slice(0, 4), out ForceArea area) || !HexAscii.TryParseDecimal(text.Slice(4, 4), out int word))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "Area name or word is not valid.");
        }

        var actions = new ForceAction[16];
        for (int i = 0; i < 16; i++)
        {
            int digit = text[8 + i] - '0';
            if (digit is not (0 or 2 or 3 or 4 or 5 or 8))
            {
                throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, $"FK action for bit {15 - i} is not valid.");
            }

            actions[i] = (ForceAction)digit;
        }

        return CModeCommandParser.Checked(() => new MultipleForceCommand(area, word, actions));
    }

    private static void Execute(MultipleForceCommand command, ICModePlc plc)
    {
        (PlcArea area, int word) = CModeAddressing.Locate(command.Area, command.Word);
        bool flag = area is PlcArea.Timer or PlcArea.Counter;
        for (int i = 0; i < 16; i++)
        {
            int bit = 15 - i;
            ForceAction action = command.Actions[i];
            if (flag && bit != 15)
            {
                continue;
            }

            int target = flag ? 0 : bit;
            switch (action)
            {
                case ForceAction.Reset or ForceAction.Set:
                    if (flag)
                    {
                        plc.SetFlag(area, word, action == ForceAction.Set);
                    }
                    else
                    {
                        plc.SetBit(area, word, target, action == ForceAction.Set);
                    }

                    break;
                case ForceAction.ForcedReset or ForceAction.ForcedSet:
                    plc.ForceBit(area, word, target, action == ForceAction.ForcedSet);
                    break;
                case ForceAction.Cancel:
                    plc.ReleaseForced(area, word, target);
                    break;
            }
        }
    }

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
