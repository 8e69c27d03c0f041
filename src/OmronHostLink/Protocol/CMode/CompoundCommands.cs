namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// QQ, the compound read (W342 4-3-35/36; C200HS 11-3-33; CPM1 4-5-30): QQMR registers up to 128 bits, words and
/// timers/counters, and each QQIR reads them all in registration order. The registration is the PLC's, per unit, and
/// lasts until replaced or the PLC restarts; QQIR with nothing registered is answered with end code 19.
/// </summary>
internal static class CompoundCommands
{
    /// <summary>The sub-header of the registration.</summary>
    public const string Register = "MR";

    /// <summary>The sub-header of the read.</summary>
    public const string Read = "IR";

    /// <summary>The PLC-side state key of a unit's registration.</summary>
    internal const string RegistrationKey = "QQ";

    /// <summary>Characters before the data of a QQIR answer's text: sub-header and end code.</summary>
    public const int AnswerFixed = 2 + CModeResponse.EndCodeLength;

    /// <summary>QQMR: REGISTER I/O MEMORY. Divided into frames when long (W342: "the data can be divided into multiple frames").</summary>
    public static CModeCommandRow RegisterRow { get; } = new("QQ", "REGISTER I/O MEMORY (QQMR)", CommandEffect.Idempotent, AnswerFixed)
    {
        SubHeader = Register,
        MultiFrameCommand = true,
        Parse = static text => CompoundRegisterCommand.Parse(text),
        Execute = static (command, plc, unit) =>
        {
            plc.SetUnitState(unit, RegistrationKey, ((CompoundRegisterCommand)command).Items);
            return CModeReply.EndCodeOnly(EndCode.NormalCompletion, Register);
        },
        DescribeCommand = static (command, fields) =>
        {
            IReadOnlyList<CompoundItem> items = ((CompoundRegisterCommand)command).Items;
            fields.Field("items", items.Select(i => i.ToString()).ToArray());
            fields.Field("weight", (long)items.Sum(i => i.Weight));
        },
    };

    /// <summary>QQIR: READ I/O MEMORY: the registered items, comma-separated, in as many frames as they need.</summary>
    public static CModeCommandRow ReadRow { get; } = CreateReadRow();

    /// <summary>The QQIR command (its text is the sub-header alone).</summary>
    public static CModeCommand ReadCommand { get; } = new SimpleCommand(ReadRow, "IR"u8);

    /// <summary>Characters of the data of a QQIR answer to <paramref name="items"/>: each item and a comma between two.</summary>
    public static int DataLength(IReadOnlyList<CompoundItem> items)
    {
        int length = 0;
        foreach (CompoundItem item in items)
        {
            length += item.AnswerLength;
        }

        return DataLength(items.Count, length);
    }

    /// <summary>Characters of the data of a QQIR answer to <paramref name="items"/> items that take <paramref name="itemCharacters"/> in all: the items and a comma between two.</summary>
    public static int DataLength(int items, int itemCharacters) => itemCharacters + Math.Max(0, items - 1);

    /// <summary>
    /// Reads the data of a QQIR answer (after sub-header and end code) registered as <paramref name="items"/>: one value
    /// per item (a bit or flag 0/1, a word, a timer/counter's PV); the answer must have exactly the registration's shape.
    /// </summary>
    /// <param name="data">The data.</param>
    /// <param name="items">The registration.</param>
    /// <param name="values">One value per item.</param>
    /// <param name="flags">For each timer/counter read with CH, its completion flag (0/1); other entries 0. May be empty.</param>
    /// <exception cref="HostLinkFrameException">The data does not have the registration's shape.</exception>
    public static void ReadData(ReadOnlySpan<byte> data, IReadOnlyList<CompoundItem> items, Span<ushort> values, Span<ushort> flags = default)
    {
        int expected = DataLength(items);
        if (data.Length != expected)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"A QQIR answer to {items.Count} registered items carries {expected} characters of data; this one carries {data.Length}.", data);
        }

        int at = 0;
        for (int i = 0; i < items.Count; i++)
        {
            if (i > 0)
            {
                if (data[at] != (byte)',')
                {
                    throw new HostLinkFrameException(FrameError.Malformed, $"The items of a QQIR answer are separated by ','; '{(char)data[at]}' stands before item {i + 1}.", data);
                }

                at++;
            }

            CompoundItem item = items[i];
            if (item.IsBit || item.IsTimerCounterWord)
            {
                byte on = data[at];
                if (on is not ((byte)'0' or (byte)'1'))
                {
                    throw new HostLinkFrameException(FrameError.Malformed, $"Item {i + 1} of a QQIR answer ({item}) is a bit or flag, 0 or 1; it is '{(char)on}'.", data);
                }

                if (item.IsBit)
                {
                    values[i] = (ushort)(on - '0');
                    at++;
                    continue;
                }

                if (!flags.IsEmpty)
                {
                    flags[i] = (ushort)(on - '0');
                }

                at++;
            }

            if (!HexAscii.TryParseWord(data.Slice(at, 4), out ushort word))
            {
                throw new HostLinkFrameException(FrameError.Malformed, $"Item {i + 1} of a QQIR answer ({item}) is a word of four hex digits.", data);
            }

            values[i] = word;
            at += 4;
        }
    }

    /// <summary>
    /// The data of a QQIR answer without its registration (for <c>explain</c>): the comma-separated items as they
    /// stand, each a bit (1 character), a word (4) or a timer/counter flag and PV (5).
    /// </summary>
    internal static void DescribeData(ReadOnlySpan<byte> data, ICommandFields fields)
    {
        var items = new List<string>();
        int start = 0;
        for (int i = 0; i <= data.Length; i++)
        {
            if (i < data.Length && data[i] != (byte)',')
            {
                continue;
            }

            ReadOnlySpan<byte> item = data.Slice(start, i - start);
            bool ok = item.Length switch
            {
                1 => item[0] is (byte)'0' or (byte)'1',
                4 => HexAscii.IsHex(item),
                5 => item[0] is (byte)'0' or (byte)'1' && HexAscii.IsHex(item.Slice(1)),
                _ => false,
            };
            if (!ok)
            {
                fields.Problem($"Item {items.Count + 1} of the QQIR answer, '{FrameText.Printable(item)}', is neither a bit (0/1), a word (4 hex digits) nor a timer/counter flag and PV (5).");
                return;
            }

            items.Add(System.Text.Encoding.ASCII.GetString(item.ToArray()));
            start = i + 1;
        }

        if (data.IsEmpty)
        {
            fields.Problem("A QQIR answer with end code 00 carries the registered items.");
            return;
        }

        fields.Field("items", items.ToArray());
        if (!fields.Final)
        {
            fields.Note("More items follow in the next frames (the host asks for each with a bare CR).");
        }
    }

    private static CModeCommandRow CreateReadRow()
        => new("QQ", "READ I/O MEMORY (QQIR)", CommandEffect.ReadOnly, AnswerFixed + DataLength(CompoundItem.MaxWeight, CompoundItem.MaxWeight * CompoundItem.WordAnswerLength))
        {
            SubHeader = Read,
            Parse = static text =>
            {
                CModeCommandParser.ExpectLength(text, 0, "QQIR");
                return ReadCommand;
            },
            Execute = static (_, plc, unit) => Execute(plc, unit),
            DescribeAnswer = DescribeData,
        };

    private static CModeReply Execute(ICModePlc plc, int unit)
    {
        if (plc.GetUnitState(unit, RegistrationKey) is not IReadOnlyList<CompoundItem> items)
        {
            return CModeReply.EndCodeOnly(EndCode.NotExecutable, Read);
        }

        var data = new byte[DataLength(items)];
        int at = 0;
        for (int i = 0; i < items.Count; i++)
        {
            if (i > 0)
            {
                data[at++] = (byte)',';
            }

            CompoundItem item = items[i];
            (PlcArea area, int word, int bank) = item.Locate();
            if (item.Area is CompoundArea.Timer or CompoundArea.Counter)
            {
                data[at++] = plc.GetFlag(area, word) ? (byte)'1' : (byte)'0';
                if (item.IsBit)
                {
                    continue;
                }
            }
            else if (item.IsBit)
            {
                data[at++] = ((plc.ReadWord(area, word, bank) >> item.Bit) & 1) == 1 ? (byte)'1' : (byte)'0';
                continue;
            }

            HexAscii.WriteWord(plc.ReadWord(area, word, bank), data.AsSpan(at, 4));
            at += 4;
        }

        // Cut anywhere between characters when the answer spans frames; the host joins the frames' text.
        return CModeReply.Ok(EndCode.NormalCompletion, Read, data, atomLength: 1);
    }
}

/// <summary>QQMR: the items to register, comma-separated; the command spans frames when long, cut before a comma.</summary>
internal sealed class CompoundRegisterCommand : CModeCommand
{
    private readonly CompoundItem[] _items;

    /// <summary>Creates the command.</summary>
    /// <exception cref="ArgumentException">No items, or more than 128 (a timer/counter PV counts as two).</exception>
    public CompoundRegisterCommand(IReadOnlyList<CompoundItem> items)
    {
        Guard.NotNull(items);
        int weight = items.Sum(i => i.Weight);
        if (items.Count == 0 || weight > CompoundItem.MaxWeight)
        {
            throw new ArgumentException($"QQMR registers 1-{CompoundItem.MaxWeight} items (a timer/counter PV counts as two); these weigh {weight}.", nameof(items));
        }

        _items = items.ToArray();
    }

    /// <summary>The items, in registration (and answer) order.</summary>
    public IReadOnlyList<CompoundItem> Items => _items;

    /// <inheritdoc/>
    public override CModeCommandRow Row => CompoundCommands.RegisterRow;

    /// <inheritdoc/>
    public override int TextLength => GetTextLength(_items.Length);

    /// <summary>The sub-header and the first item stay in the first frame.</summary>
    public override int FixedTextLength => GetTextLength(1);

    /// <summary>Later items travel as ",item": a frame is cut before a comma.</summary>
    public override int AtomLength => ItemAtomLength;

    /// <summary>Characters of a later item with the comma before it: what a frame of the command is cut between.</summary>
    public const int ItemAtomLength = CompoundItem.Length + 1;

    /// <summary>Characters of the text registering <paramref name="items"/> items: the sub-header, then the items with a comma between two.</summary>
    public static int GetTextLength(int items) => CompoundCommands.Register.Length + (items * ItemAtomLength) - 1;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
        destination[0] = (byte)'M';
        destination[1] = (byte)'R';
        int at = 2;
        for (int i = 0; i < _items.Length; i++)
        {
            if (i > 0)
            {
                destination[at++] = (byte)',';
            }

            _items[i].Write(destination.Slice(at, CompoundItem.Length));
            at += CompoundItem.Length;
        }
    }

    /// <summary>
    /// Reads the items as a PLC does: 14 when an item or the comma between two is missing (a comma at the very end is
    /// taken), 15 for an area, word or format out of range.
    /// </summary>
    internal static CompoundRegisterCommand Parse(ReadOnlySpan<byte> text)
    {
        if (!text.IsEmpty && text[text.Length - 1] == (byte)',')
        {
            text = text.Slice(0, text.Length - 1);
        }

        var items = new List<CompoundItem>();
        int weight = 0;
        int start = 0;
        for (int i = 0; i <= text.Length; i++)
        {
            if (i < text.Length && text[i] != (byte)',')
            {
                continue;
            }

            ReadOnlySpan<byte> field = text.Slice(start, i - start);
            if (field.Length != CompoundItem.Length)
            {
                throw CModeCommandParser.Reject(EndCode.FormatError, $"QQMR items are {CompoundItem.Length} characters, separated by ','.");
            }

            if (!CompoundItem.TryParse(field, out CompoundItem item, out string? fault))
            {
                throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, fault!);
            }

            weight += item.Weight;
            if (weight > CompoundItem.MaxWeight)
            {
                throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, $"QQMR registers at most {CompoundItem.MaxWeight} items (a timer/counter PV counts as two).");
            }

            items.Add(item);
            start = i + 1;
        }

        return new CompoundRegisterCommand(items);
    }
}
