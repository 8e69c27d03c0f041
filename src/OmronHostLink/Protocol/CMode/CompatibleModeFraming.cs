namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// How a Serial Communications Unit in one <see cref="HostLinkCompatibleMode"/> frames its answers: the words a frame of
/// an RR, RL, RH, RC, RD or RJ answer carries, the flags a frame of an RG answer carries, and the form of the MS answer
/// (W336 section 4-6-2, printed p141, and its mode table, printed p301; W342 section 2-4-1, printed p15, for the 29/30
/// words of C-series Host Link Units). A value the manual pages found do not give is null: nothing is checked, or
/// emulated, for it.
/// </summary>
internal sealed class CompatibleModeFraming
{
    /// <summary>The source of the table, as messages and docs cite it.</summary>
    public const string Source = "W336 (CS/CJ Serial Communications Boards/Units) section 4-6-2, printed p141 and p301";

    private static readonly CompatibleModeFraming[] Modes =
    [
        new(HostLinkCompatibleMode.ModeA, "mode A (CS/CJ/C)", 30, 31, 121, 125, statusMessageAlwaysSent: false),
        new(HostLinkCompatibleMode.ModeB, "mode B (CVM1/CV)", 30, 31, 121, 125, statusMessageAlwaysSent: true),
        new(HostLinkCompatibleMode.ModeC, "mode C (C200H)", 29, 30, 89, 89, statusMessageAlwaysSent: false),
        new(HostLinkCompatibleMode.ModeD, "mode D (C500/C120)", 29, 30, 89, null, statusMessageAlwaysSent: null),
    ];

    private CompatibleModeFraming(
        HostLinkCompatibleMode mode, string name, int wordsFirst, int wordsLater, int flagsFirst, int? flagsLater, bool? statusMessageAlwaysSent)
    {
        Mode = mode;
        Name = name;
        WordsFirstFrame = wordsFirst;
        WordsLaterFrame = wordsLater;
        FlagsFirstFrame = flagsFirst;
        FlagsLaterFrame = flagsLater;
        StatusMessageAlwaysSent = statusMessageAlwaysSent;
    }

    /// <summary>The mode.</summary>
    public HostLinkCompatibleMode Mode { get; }

    /// <summary>The mode as the manual names it: "mode C (C200H)".</summary>
    public string Name { get; }

    /// <summary>Words of an RR, RL, RH, RC, RD or RJ answer in its first frame.</summary>
    public int WordsFirstFrame { get; }

    /// <summary>Words of an RR, RL, RH, RC, RD or RJ answer in each later frame.</summary>
    public int WordsLaterFrame { get; }

    /// <summary>Completion flags of an RG answer in its first frame.</summary>
    public int FlagsFirstFrame { get; }

    /// <summary>Completion flags of an RG answer in each later frame; null where the manual pages found do not say.</summary>
    public int? FlagsLaterFrame { get; }

    /// <summary>
    /// Whether MS sends the 16 FAL/FALS message characters (spaces) when no FAL/FALS has run ("fixed length"), or
    /// leaves them out ("variable length"); null where the manual pages found do not say.
    /// </summary>
    public bool? StatusMessageAlwaysSent { get; }

    /// <summary>The framing of <paramref name="mode"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not a mode.</exception>
    public static CompatibleModeFraming Of(HostLinkCompatibleMode mode)
        => (uint)mode < (uint)Modes.Length
            ? Modes[(int)mode]
            : throw new ArgumentOutOfRangeException(nameof(mode), mode, $"{(int)mode} is not a Host Link-compatible mode (ModeA to ModeD).");

    /// <summary>
    /// The data characters one frame of an answer to <paramref name="header"/> carries at most, and the size of one
    /// entry; (0, 0) for a header whose frames the mode does not fix.
    /// </summary>
    public (int MaxData, int Entry) FrameCapacity(string header, bool first)
    {
        if (header == "RG")
        {
            int? flags = first ? FlagsFirstFrame : FlagsLaterFrame;
            return flags is { } n ? (n, 1) : (0, 0);
        }

        return IsWordRead(header) ? ((first ? WordsFirstFrame : WordsLaterFrame) * 4, 4) : (0, 0);
    }

    /// <summary>
    /// Checks one answer frame against the mode: no frame carries more entries than the mode sends, and a first frame
    /// followed by others carries exactly as many (the manuals' "the first frame can contain up to …").
    /// </summary>
    /// <param name="header">The command's header.</param>
    /// <param name="first">Whether the frame is the answer's first.</param>
    /// <param name="final">Whether the frame is the answer's last.</param>
    /// <param name="textLength">The frame's text length (in a first frame: end code and data).</param>
    /// <exception cref="HostLinkFrameException">The frame is framed as another mode frames it.</exception>
    public void CheckFrame(string header, bool first, bool final, int textLength)
    {
        (int maxData, int entry) = FrameCapacity(header, first);
        if (maxData == 0)
        {
            return;
        }

        int data = first ? textLength - CModeResponse.EndCodeLength : textLength;
        if (data > maxData || (first && !final && data != maxData))
        {
            string unit = entry == 4 ? "words" : "completion flags";
            string which = first ? "first" : "later";
            throw new HostLinkFrameException(
                FrameError.WrongLength,
                $"The {header} answer's {which} frame carried {data / entry} {unit}; a Serial Communications Unit in Host Link-compatible {Name} sends {maxData / entry}{(first && !final ? string.Empty : " at most")}. Set HostLinkCompatibleMode as the unit is set (or leave it unset to accept any framing).");
        }
    }

    private static bool IsWordRead(string header)
        => header is "RR" or "RL" or "RH" or "RC" or "RD" or "RJ";
}
