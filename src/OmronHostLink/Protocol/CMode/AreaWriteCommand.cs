namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// WR, WL, WH, WC, WD, WJ, WE: write words from <see cref="Begin"/>. Long writes span several frames; the address and
/// the first word stay in the first frame and no word is split between frames.
/// </summary>
internal sealed class AreaWriteCommand : CModeCommand
{
    private readonly ushort[] _words;

    /// <summary>Creates the command; the range is checked against the area's C-mode limits.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside what C-mode reaches (AR below A448 is read-only).</exception>
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
    public override string Header => CModeAreaInfo.WriteHeader(Area);

    /// <inheritdoc/>
    public override int FixedTextLength => GetFixedTextLength(Area);

    /// <inheritdoc/>
    public override int TextLength => FixedTextLength + (_words.Length * 4);

    /// <inheritdoc/>
    internal override CommandEffect Effect => CommandEffect.Idempotent;

    /// <inheritdoc/>
    public override int AtomLength => 4;

    /// <inheritdoc/>
    public override bool MayUseSeveralFrames => true;

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
}
