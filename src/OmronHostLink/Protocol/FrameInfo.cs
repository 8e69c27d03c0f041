namespace OmronHostLink.Protocol;

/// <summary>
/// Where the parts of one validated frame lie. For a first frame: <c>@</c>, unit, header, text, FCS, ending.
/// For a continuation frame: text, FCS, ending.
/// </summary>
internal readonly struct FrameInfo
{
    /// <summary>Creates the description of a frame.</summary>
    public FrameInfo(int unit, int textStart, int textLength, bool isFinal)
    {
        Unit = unit;
        TextStart = textStart;
        TextLength = textLength;
        IsFinal = isFinal;
    }

    /// <summary>The unit number of a first frame; -1 for a continuation frame.</summary>
    public int Unit { get; }

    /// <summary>Offset of the text (after the header in a first frame).</summary>
    public int TextStart { get; }

    /// <summary>Length of the text, FCS and ending excluded.</summary>
    public int TextLength { get; }

    /// <summary>True when the frame ends with <c>*</c>CR (last or only frame); false for a CR delimiter.</summary>
    public bool IsFinal { get; }

    /// <summary>The two header characters of a first frame.</summary>
    public ReadOnlySpan<byte> Header(ReadOnlySpan<byte> frame) => frame.Slice(3, 2);

    /// <summary>The text of the frame.</summary>
    public ReadOnlySpan<byte> Text(ReadOnlySpan<byte> frame) => frame.Slice(TextStart, TextLength);
}
