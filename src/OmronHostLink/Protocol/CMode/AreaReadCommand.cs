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
    public override string Header => CModeAreaInfo.ReadHeader(Area);

    /// <inheritdoc/>
    public override int TextLength => GetTextLength(Area);

    /// <inheritdoc/>
    public override int ResponseAtomLength => CModeAreaInfo.CharactersPerEntry(Area);

    /// <summary>Data characters a complete response carries.</summary>
    public int ResponseDataLength => Count * ResponseAtomLength;

    /// <inheritdoc/>
    internal override int MaxAnswerTextLength => CModeResponse.EndCodeLength + ResponseDataLength;

    /// <inheritdoc/>
    internal override CommandEffect Effect => CommandEffect.ReadOnly;

    /// <summary>How a read of <paramref name="count"/> entries of <paramref name="area"/> travels, without a command object (the hot path).</summary>
    internal static ExchangeShape GetExchange(CModeArea area, int count)
        => ExchangeShape.CMode(
            GetMessageLength(area),
            atomLength: 1,
            multiFrameCommand: false,
            expectsAnswer: true,
            CModeResponse.EndCodeLength + (count * CModeAreaInfo.CharactersPerEntry(area)),
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
}
