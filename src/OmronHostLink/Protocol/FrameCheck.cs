namespace OmronHostLink.Protocol;

/// <summary>
/// What one received frame's characters say, checked without throwing: its ending, where its FCS lies and whether it
/// matches, and for a first frame the unit number. <see cref="FrameParser"/> refuses a frame on the first fault it
/// finds; a diagnostic tool reports every one, in the same words.
/// </summary>
internal readonly struct FrameCheck
{
    /// <summary>Characters of <c>@</c>, unit and header before the text of a first frame.</summary>
    private const int FirstFramePrefix = MessagePrefix.Length;

    private FrameCheck(bool endsWithCr, bool isFinal, int fcsAt, int controlAt, byte expectedFcs, bool fcsMatches, int unit, bool isFirst)
    {
        EndsWithCr = endsWithCr;
        IsFinal = isFinal;
        FcsAt = fcsAt;
        ControlAt = controlAt;
        ExpectedFcs = expectedFcs;
        FcsMatches = fcsMatches;
        Unit = unit;
        IsFirst = isFirst;
    }

    /// <summary>Whether the frame ends with CR.</summary>
    public bool EndsWithCr { get; }

    /// <summary>Whether the frame ends with <c>*</c>CR (the last or only frame of a message).</summary>
    public bool IsFinal { get; }

    /// <summary>Where the two FCS characters start (the checked characters end there); -1 when the frame has no room for them.</summary>
    public int FcsAt { get; }

    /// <summary>The position of the first character outside printable ASCII before the FCS ends; -1 when there is none.</summary>
    public int ControlAt { get; }

    /// <summary>The FCS the checked characters give.</summary>
    public byte ExpectedFcs { get; }

    /// <summary>Whether the FCS characters the frame carries are the ones its characters give.</summary>
    public bool FcsMatches { get; }

    /// <summary>Whether the frame starts with <c>@</c> (a first frame; without it, a continuation frame).</summary>
    public bool IsFirst { get; }

    /// <summary>The unit number of a first frame (two decimal digits after <c>@</c>); -1 when there are none.</summary>
    public int Unit { get; }

    /// <summary>The number of text characters of a first frame, after <c>@</c>, unit and header.</summary>
    public int FirstFrameTextLength => FcsAt - FirstFramePrefix;

    /// <summary>Checks <paramref name="frame"/>, a frame up to and including its CR.</summary>
    public static FrameCheck Of(ReadOnlySpan<byte> frame)
    {
        bool isFirst = frame.Length > 0 && frame[0] == (byte)'@';
        int unit = MessagePrefix.TryReadUnit(frame, out int u) ? u : -1;
        if (frame.Length < 3 || frame[frame.Length - 1] != (byte)'\r')
        {
            return new FrameCheck(false, false, -1, -1, 0, false, unit, isFirst);
        }

        bool final = frame[frame.Length - 2] == (byte)'*';
        int fcsEnd = frame.Length - (final ? 2 : 1);
        int fcsAt = fcsEnd - 2;
        if (fcsAt < 0)
        {
            return new FrameCheck(true, final, -1, -1, 0, false, unit, isFirst);
        }

        int controlAt = -1;
        for (int i = 0; i < fcsEnd; i++)
        {
            byte c = frame[i];
            if (c < 0x20 || c > 0x7E)
            {
                controlAt = i;
                break;
            }
        }

        bool matches = Fcs.Verify(frame.Slice(0, fcsAt), frame.Slice(fcsAt, 2), out byte expected);
        return new FrameCheck(true, final, fcsAt, controlAt, expected, matches, unit, isFirst);
    }

    /// <summary>
    /// What is wrong with the frame's shape, whatever kind of frame it is: no CR at the end, no room for an FCS, or a
    /// character outside printable ASCII. Null when the shape is sound.
    /// </summary>
    public string? ShapeFault(ReadOnlySpan<byte> frame)
    {
        if (!EndsWithCr)
        {
            return Malformed("it does not end with CR");
        }

        if (FcsAt < 0)
        {
            return Malformed("it is too short to hold an FCS");
        }

        return ControlAt < 0 ? null : Malformed($"it contains the non-printable character 0x{frame[ControlAt]:X2} at position {ControlAt}");
    }

    /// <summary>
    /// What is wrong with the start of a first frame whose shape is sound: no room for a unit number, a header and an
    /// FCS, or a unit number that is not two digits. Null when the start is sound.
    /// </summary>
    public string? FirstFrameFault(ReadOnlySpan<byte> frame)
    {
        if (FcsAt < FirstFramePrefix)
        {
            return Malformed("it is too short to hold a unit number, a header and an FCS");
        }

        return Unit >= 0 ? null : $"The unit number '{FrameText.Printable(frame.Slice(1, 2))}' is not two decimal digits.";
    }

    /// <summary>The FCS mismatch in words, or null when the FCS matches (or the frame has none).</summary>
    public string? FcsFault(ReadOnlySpan<byte> frame)
        => FcsMatches || FcsAt < 0
            ? null
            : $"FCS error: the frame carries '{FrameText.Printable(frame.Slice(FcsAt, 2))}' but its characters give '{ExpectedFcs:X2}'.";

    /// <summary>The sentence for a malformed frame.</summary>
    internal static string Malformed(string why) => $"The frame is malformed: {why}.";
}
