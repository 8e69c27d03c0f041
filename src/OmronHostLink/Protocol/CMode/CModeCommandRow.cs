namespace OmronHostLink.Protocol.CMode;

/// <summary>Rebuilds a command from the text after its header (and sub-header), as a PLC reads it; refuses with <see cref="CModeCommandRejectedException"/>.</summary>
internal delegate CModeCommand CModeParse(ReadOnlySpan<byte> text);

/// <summary>Executes a parsed command against the PLC side; null when the PLC sends no answer.</summary>
internal delegate CModeReply? CModeExecute(CModeCommand command, ICModePlc plc, int unit);

/// <summary>
/// Checks the text of one frame of a command the host divides into frames, as the PLC does on receiving it: null when
/// it may be taken, else the end code the PLC answers (first frame: 14, 15; later frames: A3, A4, A5).
/// </summary>
internal delegate EndCode? CModeFrameCheck(ReadOnlySpan<byte> text, bool first);

/// <summary>Puts a parsed command's fields into <paramref name="fields"/>.</summary>
internal delegate void CModeDescribeCommand(CModeCommand command, ICommandFields fields);

/// <summary>
/// Puts the fields of a normal-completion answer's data (after the end code) into <paramref name="fields"/>; throws
/// <see cref="HostLinkFrameException"/> or adds a problem when the data does not have the answer's shape.
/// </summary>
internal delegate void CModeDescribeAnswer(ReadOnlySpan<byte> data, ICommandFields fields);

/// <summary>
/// One C-mode command as the manuals define it, in one place: header (and sub-header), manual name, what repeating it
/// does, the longest answer, whether the command may span frames, and how to parse, execute (PLC side), describe and
/// decode it. The parser, the simulator, <c>explain</c> and its direction guess all read these rows
/// (<see cref="CModeCommandTable"/>); a PLC model profile names the rows its model accepts.
/// </summary>
internal sealed class CModeCommandRow
{
    /// <summary>Creates a row.</summary>
    /// <param name="header">The two header characters.</param>
    /// <param name="name">The manuals' name (W342 section 4).</param>
    /// <param name="effect">What repeating the command would do.</param>
    /// <param name="maxAnswerText">The longest answer text after the header (sub-header, end code and data, every frame joined).</param>
    public CModeCommandRow(string header, string name, CommandEffect effect, int maxAnswerText)
    {
        if (Guard.NotNull(header).Length != 2)
        {
            throw new ArgumentException("A header has two characters.", nameof(header));
        }

        Header = header;
        Name = Guard.NotNull(name);
        Effect = effect;
        MaxAnswerText = maxAnswerText;
    }

    /// <summary>The two header characters (<c>RD</c>, <c>QQ</c>).</summary>
    public string Header { get; }

    /// <summary>The two characters after the header that pick the command (<c>MR</c>, <c>IR</c> of QQ); null for none.</summary>
    public string? SubHeader { get; init; }

    /// <summary>The manuals' name.</summary>
    public string Name { get; }

    /// <summary>What repeating the command would do (a command may refine it: MF with clearing is not repeatable).</summary>
    public CommandEffect Effect { get; }

    /// <summary>The longest answer text after the header that any command of this row can get.</summary>
    public int MaxAnswerText { get; }

    /// <summary>Whether the host may divide the command into frames (area writes, QQMR).</summary>
    public bool MultiFrameCommand { get; init; }

    /// <summary>How the PLC checks each frame of a divided command (rows with <see cref="MultiFrameCommand"/>); null takes any frame.</summary>
    public CModeFrameCheck? CheckFrame { get; init; }

    /// <summary>Whether the PLC answers (XZ and INITIALIZE: no).</summary>
    public bool ExpectsAnswer { get; init; } = true;

    /// <summary>Whether the answer starts with an end code (TS, IC and EX: no).</summary>
    public bool AnswerHasEndCode { get; init; } = true;

    /// <summary>Whether the row is a command the host sends (false for answers only: IC, EX).</summary>
    public bool IsCommand { get; init; } = true;

    /// <summary>How the PLC reads the text; null for a header this library names but does not execute.</summary>
    public CModeParse? Parse { get; init; }

    /// <summary>How the PLC executes it; null for a header this library names but does not execute.</summary>
    public CModeExecute? Execute { get; init; }

    /// <summary>The command's fields for <c>explain</c>; null for a command without fields.</summary>
    public CModeDescribeCommand? DescribeCommand { get; init; }

    /// <summary>The fields of a normal-completion answer's data; null when such an answer carries no data.</summary>
    public CModeDescribeAnswer? DescribeAnswer { get; init; }

    /// <summary>Whether a PLC of this library executes the row (it parses and executes it).</summary>
    public bool IsExecutable => Parse is not null && Execute is not null;

    /// <summary>The header and sub-header, the row's key (<c>RD</c>, <c>QQIR</c>).</summary>
    public string Key => Header + SubHeader;

    /// <summary>Characters of the text the sub-header takes.</summary>
    public int SubHeaderLength => SubHeader?.Length ?? 0;

    /// <inheritdoc/>
    public override string ToString() => $"{Key} {Name}";
}
