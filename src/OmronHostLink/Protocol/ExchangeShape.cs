namespace OmronHostLink.Protocol;

/// <summary>
/// How one command travels and is answered, as the command itself knows it: which part of the message must stay in the
/// first frame, whether the message may be divided, the longest answer, and whether a correct answer can be the same
/// characters as the command. The link carries any exchange from this alone, without knowing C-mode or FINS.
/// </summary>
internal readonly struct ExchangeShape
{
    /// <summary><c>@</c>, unit, header, FCS, <c>*</c>, CR around an answer's text.</summary>
    public const int AnswerOverhead = 9;

    private ExchangeShape(int fixedLength, int atomLength, bool multiFrameCommand, bool singleFrameOnly, bool expectsAnswer, int maxAnswerText, bool answerCanEqualCommand)
    {
        FixedLength = fixedLength;
        AtomLength = atomLength;
        MultiFrameCommand = multiFrameCommand;
        SingleFrameOnly = singleFrameOnly;
        ExpectsAnswer = expectsAnswer;
        MaxAnswerText = maxAnswerText;
        AnswerCanEqualCommand = answerCanEqualCommand;
    }

    /// <summary>Characters of the message that must stay in the first frame.</summary>
    public int FixedLength { get; }

    /// <summary>Units the rest of the message may be cut between.</summary>
    public int AtomLength { get; }

    /// <summary>Whether the command may span frames (area writes).</summary>
    public bool MultiFrameCommand { get; }

    /// <summary>FINS frames: one frame of any length both ways, never partitioned.</summary>
    public bool SingleFrameOnly { get; }

    /// <summary>Whether the PLC answers (XZ: no).</summary>
    public bool ExpectsAnswer { get; }

    /// <summary>The most answer text (end code and data, every frame joined) a correct answer holds; more is a frame error.</summary>
    public int MaxAnswerText { get; }

    /// <summary>
    /// Whether a correct answer can be the very characters of the command: TS echoes its command, and a command whose
    /// text is two characters (SC 00, MF 01) reads the same as an answer carrying only an end code.
    /// </summary>
    public bool AnswerCanEqualCommand { get; }

    /// <summary>The longest first answer frame.</summary>
    public int MaxFirstAnswerFrame => SingleFrameOnly
        ? AnswerOverhead + MaxAnswerText
        : Math.Min(FrameWriter.MaxFirstFrameLength, AnswerOverhead + MaxAnswerText);

    /// <summary>
    /// Whether the answer may continue beyond its first frame: the PLC then holds the rest until asked, so an answer cut
    /// after its first frame leaves the line in the middle of an exchange.
    /// </summary>
    public bool AnswerMaySpanFrames => !SingleFrameOnly && AnswerOverhead + MaxAnswerText > FrameWriter.MaxFirstFrameLength;

    /// <summary>A C-mode exchange.</summary>
    public static ExchangeShape CMode(int fixedLength, int atomLength, bool multiFrameCommand, bool expectsAnswer, int maxAnswerText, bool answerCanEqualCommand)
        => new(fixedLength, atomLength, multiFrameCommand, singleFrameOnly: false, expectsAnswer, maxAnswerText, answerCanEqualCommand);

    /// <summary>An FA (FINS) exchange: one frame each way, always answered.</summary>
    public static ExchangeShape Fins(int messageLength, int maxAnswerText)
        => new(messageLength, 1, multiFrameCommand: false, singleFrameOnly: true, expectsAnswer: true, maxAnswerText, answerCanEqualCommand: false);
}
