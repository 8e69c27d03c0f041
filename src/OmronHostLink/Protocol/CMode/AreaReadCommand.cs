namespace OmronHostLink.Protocol.CMode;

/// <summary>RR, RL, RH, RC, RG, RD, RJ, RE: read <see cref="Count"/> entries from <see cref="Begin"/> (EM: in <see cref="Bank"/>).</summary>
internal sealed class AreaReadCommand : CModeCommand
{
    /// <summary>Creates the command; the range is checked against the area's C-mode limits.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside what C-mode reaches.</exception>
    public AreaReadCommand(CModeArea area, int begin, int count, int bank = 0)
    {
        CModeAreaInfo.CheckRange(area, begin, count, bank, write: false);
        Area = area;
        Begin = begin;
        Count = count;
        Bank = bank;
    }

    /// <summary>The area read.</summary>
    public CModeArea Area { get; }

    /// <summary>The first entry.</summary>
    public int Begin { get; }

    /// <summary>The number of entries.</summary>
    public int Count { get; }

    /// <summary>The EM bank (RE only).</summary>
    public int Bank { get; }

    /// <inheritdoc/>
    public override CModeCommandRow Row => Rows[(int)Area];

    /// <inheritdoc/>
    public override int TextLength => GetTextLength(Area);

    /// <inheritdoc/>
    public override int ResponseAtomLength => CModeAreaInfo.CharactersPerEntry(Area);

    /// <summary>Data characters a complete response carries.</summary>
    public int ResponseDataLength => Count * ResponseAtomLength;

    /// <inheritdoc/>
    internal override int MaxAnswerTextLength => MaxAnswerText(Area, Count);

    /// <inheritdoc/>
    internal override ExchangeShape Exchange => GetExchange(Area, Count);

    /// <summary>The one row per area (RR, RL, RH, RC, RG, RD, RJ, RE), by <see cref="CModeArea"/>.</summary>
    internal static CModeCommandRow[] Rows { get; } = CreateRows();

    /// <summary>The answer text of a read of <paramref name="count"/> entries: end code and the entries.</summary>
    internal static int MaxAnswerText(CModeArea area, int count) => CModeResponse.EndCodeLength + (count * CModeAreaInfo.CharactersPerEntry(area));

    /// <summary>How a read of <paramref name="count"/> entries of <paramref name="area"/> travels (what the command object's <see cref="Exchange"/> is): one frame out, the answer in as many as it needs.</summary>
    internal static ExchangeShape GetExchange(CModeArea area, int count)
        => ExchangeShape.CMode(
            GetMessageLength(area),
            atomLength: 1,
            multiFrameCommand: false,
            expectsAnswer: true,
            MaxAnswerText(area, count),
            answerCanEqualCommand: false);

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => Write(Area, Begin, Count, Bank, destination);

    /// <summary>The length of the unframed message (<c>@</c>, unit, header, text) of a read of <paramref name="area"/>.</summary>
    public static int GetMessageLength(CModeArea area) => PrefixLength + GetTextLength(area);

    /// <summary>The length of the text of a read of <paramref name="area"/>: bank (EM only), begin word and count, 4 digits each.</summary>
    public static int GetTextLength(CModeArea area) => CModeAreaInfo.BankLength(area) + 8;

    /// <summary>The length of the framed command (message, FCS, <c>*</c>, CR) of a read of <paramref name="area"/>; a read command is always one frame.</summary>
    public static int GetFrameLength(CModeArea area) => GetMessageLength(area) + FrameWriter.FinalOverhead;

    /// <summary>
    /// Writes the unframed message <c>@</c> + unit + header + text of a read command without creating a command object
    /// (the hot path). The range is checked as the constructor checks it.
    /// </summary>
    /// <returns>The number of characters written (<see cref="GetMessageLength"/>).</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31 or the range is outside what C-mode reaches.</exception>
    /// <exception cref="ArgumentException"><paramref name="destination"/> is shorter than <see cref="GetMessageLength"/>.</exception>
    public static int WriteMessage(int unit, CModeArea area, int begin, int count, int bank, Span<byte> destination)
    {
        Guard.Unit(unit);
        CModeAreaInfo.CheckRange(area, begin, count, bank, write: false);
        int length = GetMessageLength(area);
        if (destination.Length < length)
        {
            throw new ArgumentException($"The destination holds {destination.Length} characters; the message needs {length}.", nameof(destination));
        }

        MessagePrefix.Write(destination, unit, CModeAreaInfo.ReadHeader(area));
        return PrefixLength + Write(area, begin, count, bank, destination.Slice(PrefixLength));
    }

    /// <summary>
    /// Writes the complete command frame (message, FCS, <c>*</c>, CR) of a read without creating a command object or
    /// any array: what goes on the wire.
    /// </summary>
    /// <returns>The number of characters written (<see cref="GetFrameLength"/>).</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31 or the range is outside what C-mode reaches.</exception>
    /// <exception cref="ArgumentException"><paramref name="destination"/> is shorter than <see cref="GetFrameLength"/>.</exception>
    public static int WriteFrame(int unit, CModeArea area, int begin, int count, int bank, Span<byte> destination)
    {
        if (destination.Length < GetFrameLength(area))
        {
            throw new ArgumentException($"The destination holds {destination.Length} characters; the frame needs {GetFrameLength(area)}.", nameof(destination));
        }

        int length = WriteMessage(unit, area, begin, count, bank, destination);
        return FrameWriter.WriteFrame(destination.Slice(0, length), final: true, destination);
    }

    /// <summary>Writes the text of a read command without creating a command object (the hot path).</summary>
    /// <returns>The number of characters written.</returns>
    public static int Write(CModeArea area, int begin, int count, int bank, Span<byte> destination)
    {
        int i = CModeAreaInfo.WriteBank(area, bank, destination);
        HexAscii.WriteDecimal(begin, destination.Slice(i, 4));
        HexAscii.WriteDecimal(count, destination.Slice(i + 4, 4));
        return i + 8;
    }

    private static CModeCommandRow[] CreateRows()
    {
        var rows = new CModeCommandRow[8];
        foreach (CModeArea area in new[] { CModeArea.Cio, CModeArea.Lr, CModeArea.Holding, CModeArea.TimerCounterPv, CModeArea.TimerCounterStatus, CModeArea.Dm, CModeArea.Auxiliary, CModeArea.Em })
        {
            rows[(int)area] = new CModeCommandRow(CModeAreaInfo.ReadHeader(area), ReadName(area), CommandEffect.ReadOnly, MaxAnswerText(area, CModeAreaInfo.Size(area)))
            {
                Parse = text => Parse(area, text),
                Execute = static (command, plc, _) => Execute((AreaReadCommand)command, plc),
                DescribeCommand = static (command, fields) =>
                {
                    var r = (AreaReadCommand)command;
                    DescribeRange(fields, r.Area, r.Bank, r.Begin, r.Count);
                },
                DescribeAnswer = area == CModeArea.TimerCounterStatus ? DescribeFlags : DescribeWords,
            };
        }

        return rows;
    }

    private static string ReadName(CModeArea area) => area switch
    {
        CModeArea.Cio => "CIO AREA READ",
        CModeArea.Lr => "LR AREA READ",
        CModeArea.Holding => "HR AREA READ",
        CModeArea.TimerCounterPv => "TIMER/COUNTER PV READ",
        CModeArea.TimerCounterStatus => "TIMER/COUNTER STATUS READ",
        CModeArea.Dm => "DM AREA READ",
        CModeArea.Auxiliary => "AR AREA READ",
        _ => "EM AREA READ",
    };

    private static AreaReadCommand Parse(CModeArea area, ReadOnlySpan<byte> text)
    {
        int bankLength = CModeAreaInfo.BankLength(area);
        CModeCommandParser.ExpectLength(text, GetTextLength(area), CModeAreaInfo.ReadHeader(area));
        int bank = ParseBank(area, text);
        if (!HexAscii.TryParseDecimal(text.Slice(bankLength, 4), out int begin) || !HexAscii.TryParseDecimal(text.Slice(bankLength + 4, 4), out int count))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "Begin word and count must be decimal digits.");
        }

        return CModeCommandParser.Checked(() => new AreaReadCommand(area, begin, count, bank));
    }

    /// <summary>The EM bank at the start of an RE/WE text (0 for other areas); end code 15 when it is not two hex digits.</summary>
    internal static int ParseBank(CModeArea area, ReadOnlySpan<byte> text)
    {
        if (area != CModeArea.Em)
        {
            return 0;
        }

        if (!HexAscii.TryParseByte(text.Slice(0, 2), out byte bank))
        {
            throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "EM bank must be two hex digits.");
        }

        return bank;
    }

    private static CModeReply Execute(AreaReadCommand read, ICModePlc plc)
    {
        int atom = read.ResponseAtomLength;
        var data = new byte[read.Count * atom];
        for (int i = 0; i < read.Count; i++)
        {
            (PlcArea area, int word) = CModeAddressing.Locate(read.Area, read.Begin + i);
            if (read.Area == CModeArea.TimerCounterStatus)
            {
                data[i] = plc.GetFlag(area, word) ? (byte)'1' : (byte)'0';
            }
            else
            {
                HexAscii.WriteWord(plc.ReadWord(area, word, read.Bank), data.AsSpan(i * 4, 4));
            }
        }

        // RG: 121 points in the first frame, 124 in later ones (C200HX RG page), one short of what 128 characters hold.
        return CModeReply.Ok(EndCode.NormalCompletion, null, data, atom, read.Area == CModeArea.TimerCounterStatus ? MaxFlagsPerLaterFrame : 0);
    }

    /// <summary>Completion flags an RG answer carries in each frame after the first.</summary>
    internal const int MaxFlagsPerLaterFrame = 124;

    /// <summary>The area, bank (EM), begin and count fields of an area command.</summary>
    internal static void DescribeRange(ICommandFields fields, CModeArea area, int bank, int begin, int count)
    {
        fields.Field("area", CModeAreaInfo.DisplayName(area));
        if (area == CModeArea.Em)
        {
            fields.Field("bank", (long)bank);
        }

        fields.Field("begin", (long)begin);
        fields.Field("count", (long)count);
    }

    private static void DescribeFlags(ReadOnlySpan<byte> data, ICommandFields fields)
    {
        var flags = new bool[data.Length];
        CModeResponse.ReadFlags(data, flags);
        fields.Field("flags", flags);
    }

    private static void DescribeWords(ReadOnlySpan<byte> data, ICommandFields fields)
    {
        if (data.Length % 4 != 0)
        {
            fields.Problem($"Read data comes in 4-digit words; {data.Length} characters is not a whole number of words.");
            return;
        }

        var words = new ushort[data.Length / 4];
        CModeResponse.ReadWords(data, words);
        fields.Field("words", ToLongs(words));
        if (!fields.Final)
        {
            fields.Note("More words follow in the next frames (the host asks for each with a bare CR).");
        }
    }

    /// <summary>Words as the long values the field views carry.</summary>
    internal static long[] ToLongs(ReadOnlySpan<ushort> words)
    {
        var result = new long[words.Length];
        for (int i = 0; i < words.Length; i++)
        {
            result[i] = words[i];
        }

        return result;
    }
}
