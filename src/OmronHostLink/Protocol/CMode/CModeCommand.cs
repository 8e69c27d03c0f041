namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// A C-mode command: a two-character header and its text. The message on the wire is <c>@</c> + unit + header + text,
/// framed by <see cref="FrameWriter"/>.
/// </summary>
internal abstract class CModeCommand
{
    /// <summary>Characters before the text: <c>@</c>, two unit digits, two header characters.</summary>
    public const int PrefixLength = MessagePrefix.Length;

    /// <summary>The command's row in the command table: header, name, effect, longest answer, and how it is parsed, executed and described.</summary>
    public abstract CModeCommandRow Row { get; }

    /// <summary>The two-character header, for example <c>RD</c>.</summary>
    public string Header => Row.Header;

    /// <summary>Length of the text after the header.</summary>
    public abstract int TextLength { get; }

    /// <summary>Characters at the start of the text that must stay in the first frame (address fields).</summary>
    public virtual int FixedTextLength => TextLength;

    /// <summary>Units the rest of the text may be cut between when the command spans frames (4 for word data).</summary>
    public virtual int AtomLength => 1;

    /// <summary>Whether the PLC answers the command (XZ gets no answer).</summary>
    public bool ExpectsResponse => Row.ExpectsAnswer;

    /// <summary>Whether the command may be divided into several frames (area writes and QQMR may).</summary>
    public bool MayUseSeveralFrames => Row.MultiFrameCommand;

    /// <summary>Characters a response spends on one data entry, for cutting a multi-frame response.</summary>
    public virtual int ResponseAtomLength => 4;

    /// <summary>The most answer text (sub-header, end code and data, every frame joined) a correct answer holds. Default: the row's.</summary>
    internal virtual int MaxAnswerTextLength => Row.MaxAnswerText;

    /// <summary>What repeating the command would do. Default: the row's.</summary>
    internal virtual CommandEffect Effect => Row.Effect;

    /// <summary>How the command travels and is answered.</summary>
    internal virtual ExchangeShape Exchange => ExchangeShape.CMode(
        PrefixLength + FixedTextLength,
        AtomLength,
        MayUseSeveralFrames,
        ExpectsResponse,
        MaxAnswerTextLength,
        AnswerCanEqualCommand(Header, TextLength - Row.SubHeaderLength));

    /// <summary>
    /// Whether a correct answer can be the very characters of a command: TS echoes it, and a two-character text (SC 00,
    /// MF 01) reads the same as an answer carrying only an end code.
    /// </summary>
    internal static bool AnswerCanEqualCommand(string header, int textLength)
        => header == CModeCommands.Test.Header || textLength == CModeResponse.EndCodeLength;

    /// <summary>Length of the unframed message: prefix and text.</summary>
    public int MessageLength => PrefixLength + TextLength;

    /// <summary>Writes the text after the header.</summary>
    public abstract void WriteText(Span<byte> destination);

    /// <summary>Writes the unframed message <c>@</c> + unit + header + text.</summary>
    /// <returns>The number of characters written.</returns>
    public int WriteMessage(int unit, Span<byte> destination)
    {
        MessagePrefix.Write(destination, unit, Header);
        WriteText(destination.Slice(PrefixLength, TextLength));
        return MessageLength;
    }

    /// <summary>The unframed message as a new array.</summary>
    public byte[] ToMessage(int unit)
    {
        var message = new byte[MessageLength];
        WriteMessage(unit, message);
        return message;
    }

    /// <summary>
    /// Rebuilds a typed command from a received header and text, as a PLC does. A command the PLC would refuse raises
    /// <see cref="CModeCommandRejectedException"/> carrying the end code the PLC answers with.
    /// </summary>
    public static CModeCommand Parse(ReadOnlySpan<byte> header, ReadOnlySpan<byte> text) => CModeCommandParser.Parse(CModeCommandTable.Standard, header, text);

    /// <summary>The header and text in printable form.</summary>
    public override string ToString()
    {
        Span<byte> text = TextLength <= 256 ? stackalloc byte[TextLength] : new byte[TextLength];
        WriteText(text);
        return Header + FrameText.Printable(text);
    }
}
