namespace OmronHostLink.Protocol.CMode;

/// <summary>RR, RL, RH, RC, RG, RD, RJ, RE: read <see cref="Count"/> entries from <see cref="Begin"/> (EM: in <see cref="Bank"/>).</summary>
public sealed class AreaReadCommand : CModeCommand
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
    public override int TextLength => Area == CModeArea.Em ? 10 : 8;

    /// <inheritdoc/>
    public override int ResponseAtomLength => CModeAreaInfo.CharactersPerEntry(Area);

    /// <summary>Data characters a complete response carries.</summary>
    public int ResponseDataLength => Count * ResponseAtomLength;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => Write(Area, Begin, Count, Bank, destination);

    /// <summary>Writes the text of a read command without creating a command object (the hot path).</summary>
    /// <returns>The number of characters written.</returns>
    public static int Write(CModeArea area, int begin, int count, int bank, Span<byte> destination)
    {
        int i = 0;
        if (area == CModeArea.Em)
        {
            HexAscii.WriteByte((byte)bank, destination);
            i = 2;
        }

        HexAscii.WriteDecimal(begin, destination.Slice(i, 4));
        HexAscii.WriteDecimal(count, destination.Slice(i + 4, 4));
        return i + 8;
    }
}
