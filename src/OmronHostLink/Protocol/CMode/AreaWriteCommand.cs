namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// WR, WL, WH, WC, WD, WJ, WE: write words from <see cref="Begin"/>. Long writes span several frames; the address and
/// the first word stay in the first frame and no word is split between frames.
/// </summary>
internal sealed class AreaWriteCommand : CModeCommand
{
    private readonly ushort[] _words;

    /// <summary>Creates the command; the range is checked against the area's C-mode limits.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside what C-mode reaches.</exception>
    public AreaWriteCommand(CModeArea area, int begin, ReadOnlySpan<ushort> words, int bank = 0)
    {
        CModeAreaInfo.CheckRange(area, begin, words.Length, bank, write: true);
        Area = area;
        Begin = begin;
        Bank = bank;
        _words = words.ToArray();
    }

    /// <summary>The area written.</summary>
    public CModeArea Area { get; }

    /// <summary>The first word.</summary>
    public int Begin { get; }

    /// <summary>The EM bank (WE only).</summary>
    public int Bank { get; }

    /// <summary>The words written.</summary>
    public ReadOnlySpan<ushort> Words => _words;

    /// <inheritdoc/>
    public override CModeCommandRow Row => Rows[(int)Area]!;

    /// <inheritdoc/>
    public override int FixedTextLength => GetFixedTextLength(Area);

    /// <inheritdoc/>
    public override int TextLength => FixedTextLength + (_words.Length * 4);

    /// <inheritdoc/>
    public override int AtomLength => 4;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => Write(Area, Begin, Bank, _words, destination);

    /// <summary>The characters of a write's text that must stay in the first frame: bank (EM only) and begin word.</summary>
    public static int GetFixedTextLength(CModeArea area) => CModeAreaInfo.BankLength(area) + 4;

    /// <summary>Writes the text of a write command without creating a command object.</summary>
    /// <returns>The number of characters written.</returns>
    public static int Write(CModeArea area, int begin, int bank, ReadOnlySpan<ushort> words, Span<byte> destination)
    {
        int i = CModeAreaInfo.WriteBank(area, bank, destination);
        HexAscii.WriteDecimal(begin, destination.Slice(i, 4));
        HexAscii.WriteWords(words, destination.Slice(i + 4, words.Length * 4));
        return i + 4 + (words.Length * 4);
    }

    /// <summary>The one row per writable area (WR, WL, WH, WC, WD, WJ, WE), by <see cref="CModeArea"/>; null for RG's area.</summary>
    internal static CModeCommandRow?[] Rows { get; } = CreateRows();

    private static CModeCommandRow?[] CreateRows()
    {
        var rows = new CModeCommandRow?[8];
        foreach (CModeArea area in new[] { CModeArea.Cio, CModeArea.Lr, CModeArea.Holding, CModeArea.TimerCounterPv, CModeArea.Dm, CModeArea.Auxiliary, CModeArea.Em })
        {
            rows[(int)area] = new CModeCommandRow(CModeAreaInfo.WriteHeader(area), WriteName(area), CommandEffect.Idempotent, CModeResponse.EndCodeLength)
            {
                MultiFrameCommand = true,
                CheckFrame = (text, first) => CheckFrame(area, text, first),
                Parse = text => Parse(area, text),
                Execute = static (command, plc, _) => Execute((AreaWriteCommand)command, plc),
                DescribeCommand = static (command, fields) =>
                {
                    var w = (AreaWriteCommand)command;
                    AreaReadCommand.DescribeRange(fields, w.Area, w.Bank, w.Begin, w.Words.Length);
                    fields.Field("words", AreaReadCommand.ToLongs(w.Words));
                },
            };
        }

        return rows;
    }

    private static string WriteName(CModeArea area) => area switch
    {
        CModeArea.Cio => "CIO AREA WRITE",
        CModeArea.Lr => "LR AREA WRITE",
        CModeArea.Holding => "HR AREA WRITE",
        CModeArea.TimerCounterPv => "TIMER/COUNTER PV WRITE",
        CModeArea.Dm => "DM AREA WRITE",
        CModeArea.Auxiliary => "AR AREA WRITE",
        _ => "EM AREA WRITE",
    };

    /// <summary>
    /// A divided write: the address and at least the first word in the first frame, in whole words; later frames whole
    /// hex words of more than two characters (W342: two or fewer abort with A3).
    /// </summary>
    private static EndCode? CheckFrame(CModeArea area, ReadOnlySpan<byte> text, bool first)
    {
        if (first)
        {
            int fixedLength = GetFixedTextLength(area);
            if (text.Length < fixedLength + 4 || (text.Length - fixedLength) % 4 != 0)
            {
                return EndCode.FormatError;
            }

            return !HexAscii.IsHex(text.Slice(fixedLength)) || !HexAscii.IsDecimal(text.Slice(fixedLength - 4, 4)) || !HexAscii.IsHex(text.Slice(0, CModeAreaInfo.BankLength(area)))
                ? EndCode.EntryNumberDataError
                : null;
        }

        if (text.Length <= 2)
        {
            return EndCode.AbortedFcsError;
        }

        if (text.Length % 4 != 0)
        {
            return EndCode.AbortedFormatError;
        }

        return HexAscii.IsHex(text) ? null : EndCode.AbortedEntryNumberDataError;
    }

    private static AreaWriteCommand Parse(CModeArea area, ReadOnlySpan<byte> text)
    {
        int fixedLength = GetFixedTextLength(area);
        if (text.Length < fixedLength + 4 || (text.Length - fixedLength) % 4 != 0)
        {
            throw CModeCommandParser.Reject(EndCode.FormatError, "Write data must be whole 4-digit words after the begin word.");
        }

        int bank = AreaReadCommand.ParseBank(area, text);
        if (!HexAscii.TryParseDecimal(text.Slice(fixedLength - 4, 4), out int begin))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "Begin word must be decimal digits.");
        }

        var words = new ushort[(text.Length - fixedLength) / 4];
        if (!HexAscii.TryParseWords(text.Slice(fixedLength), words))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "Write data must be hexadecimal.");
        }

        return CModeCommandParser.Checked(() => new AreaWriteCommand(area, begin, words, bank));
    }

    private static CModeReply Execute(AreaWriteCommand write, ICModePlc plc)
    {
        if (plc.Mode == PlcMode.Run)
        {
            return CModeReply.EndCodeOnly(EndCode.NotExecutableInRunMode);
        }

        for (int i = 0; i < write.Words.Length; i++)
        {
            (PlcArea area, int word) = CModeAddressing.Locate(write.Area, write.Begin + i);
            plc.WriteWord(area, word, write.Words[i], write.Bank);
        }

        return CModeReply.EndCodeOnly(EndCode.NormalCompletion);
    }
}
