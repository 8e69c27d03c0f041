namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// A command that is only its row and its text (MS, MM, KC, XZ, QQIR, and any command added to a table as a row alone):
/// everything about it is its row in a <see cref="CModeCommandTable"/>.
/// </summary>
internal sealed class SimpleCommand : CModeCommand
{
    private readonly byte[] _text;

    /// <summary>Creates the command of <paramref name="row"/> with <paramref name="text"/> after the header (sub-header included).</summary>
    public SimpleCommand(CModeCommandRow row, ReadOnlySpan<byte> text = default)
    {
        Row = Guard.NotNull(row);
        _text = text.ToArray();
    }

    /// <inheritdoc/>
    public override CModeCommandRow Row { get; }

    /// <summary>The text after the header.</summary>
    public ReadOnlySpan<byte> Text => _text;

    /// <inheritdoc/>
    public override int TextLength => _text.Length;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => _text.CopyTo(destination);
}

/// <summary>SC: STATUS CHANGE to PROGRAM (00), MONITOR (02) or RUN (03).</summary>
internal sealed class StatusChangeCommand : CModeCommand
{
    /// <summary>Creates the command.</summary>
    public StatusChangeCommand(PlcMode mode)
    {
        if (mode is not (PlcMode.Program or PlcMode.Monitor or PlcMode.Run))
        {
            throw new ArgumentOutOfRangeException(nameof(mode), mode, "The mode must be PROGRAM, MONITOR or RUN.");
        }

        Mode = mode;
    }

    /// <summary>The mode to change to.</summary>
    public PlcMode Mode { get; }

    /// <inheritdoc/>
    public override CModeCommandRow Row => CommandRow;

    private const string HeaderCode = "SC";

    /// <summary>SC: STATUS CHANGE.</summary>
    internal static CModeCommandRow CommandRow { get; } = new(HeaderCode, "STATUS CHANGE", CommandEffect.NotRepeatable, CModeResponse.EndCodeLength)
    {
        Parse = static text =>
        {
            CModeCommandParser.ExpectLength(text, 2, HeaderCode);
            if (!HexAscii.TryParseByte(text, out byte code) || !TryGetMode(code, out PlcMode mode))
            {
                throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "SC mode must be 00, 02 or 03.");
            }

            return new StatusChangeCommand(mode);
        },
        Execute = static (command, plc, _) =>
        {
            plc.Mode = ((StatusChangeCommand)command).Mode;
            return CModeReply.EndCodeOnly(EndCode.NormalCompletion);
        },
        DescribeCommand = static (command, fields) => fields.Field("mode", ((StatusChangeCommand)command).Mode.ToString().ToUpperInvariant()),
    };

    /// <inheritdoc/>
    public override int TextLength => 2;

    /// <summary>The SC mode code, which differs from the MS status coding: 00 PROGRAM, 02 MONITOR, 03 RUN.</summary>
    public static byte ModeCode(PlcMode mode) => mode switch
    {
        PlcMode.Program => 0x00,
        PlcMode.Monitor => 0x02,
        _ => 0x03,
    };

    /// <summary>The mode an SC mode code names; false for a code other than 00, 02 and 03.</summary>
    public static bool TryGetMode(byte code, out PlcMode mode)
    {
        foreach (PlcMode candidate in new[] { PlcMode.Program, PlcMode.Monitor, PlcMode.Run })
        {
            if (ModeCode(candidate) == code)
            {
                mode = candidate;
                return true;
            }
        }

        mode = default;
        return false;
    }

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => HexAscii.WriteByte(ModeCode(Mode), destination);
}

/// <summary>MF: ERROR READ, optionally clearing the errors (01) or not (00).</summary>
internal sealed class ErrorReadCommand : CModeCommand
{
    /// <summary>Creates the command.</summary>
    public ErrorReadCommand(bool clear) => Clear = clear;

    /// <summary>Whether the PLC clears its errors after reporting them.</summary>
    public bool Clear { get; }

    /// <inheritdoc/>
    public override CModeCommandRow Row => CommandRow;

    private const string HeaderCode = "MF";

    /// <summary>MF: ERROR READ (end code and two error words). The row's effect is the reading one; clearing is not repeatable.</summary>
    internal static CModeCommandRow CommandRow { get; } = new(HeaderCode, "ERROR READ", CommandEffect.ReadOnly, CModeResponse.EndCodeLength + 8)
    {
        Parse = static text =>
        {
            CModeCommandParser.ExpectLength(text, 2, HeaderCode);
            if (!HexAscii.TryParseDecimal(text, out int clear) || clear > 1)
            {
                throw CModeCommandParser.Reject(EndCode.EntryNumberDataError, "MF error clear must be 00 or 01.");
            }

            return new ErrorReadCommand(clear == 1);
        },
        Execute = static (command, plc, _) =>
        {
            PlcErrorInfo errors = plc.Errors;
            Span<byte> data = stackalloc byte[8];
            HexAscii.WriteWord(errors.FirstWord, data);
            HexAscii.WriteWord(errors.SecondWord, data.Slice(4));
            if (((ErrorReadCommand)command).Clear)
            {
                plc.ClearErrors();
            }

            return CModeReply.Ok(EndCode.NormalCompletion, null, data);
        },
        DescribeCommand = static (command, fields) => fields.Field("clear", ((ErrorReadCommand)command).Clear),
        DescribeAnswer = static (data, fields) =>
        {
            PlcErrorInfo errors = CModeResponse.ReadErrors(data);
            fields.Field("errorWords", new long[] { errors.FirstWord, errors.SecondWord });
            fields.Field("hasErrors", errors.HasErrors);
        },
    };

    /// <inheritdoc/>
    public override int TextLength => 2;

    /// <summary>Reading without clearing changes nothing; clearing does.</summary>
    internal override CommandEffect Effect => Clear ? CommandEffect.NotRepeatable : CommandEffect.ReadOnly;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => HexAscii.WriteDecimal(Clear ? 1 : 0, destination.Slice(0, 2));
}

/// <summary>TS: TEST. The PLC echoes the text back unchanged, with no end code.</summary>
internal sealed class TestCommand : CModeCommand
{
    /// <summary>The longest text that fits a single frame both ways.</summary>
    public const int MaxTextLength = 122;

    private readonly byte[] _text;

    /// <summary>Creates the command.</summary>
    /// <exception cref="ArgumentException">The text is too long, not printable ASCII, or holds <c>*</c>, <c>@</c> or CR (frame injection).</exception>
    public TestCommand(string text)
    {
        Guard.NotNull(text);
        if (text.Length > MaxTextLength)
        {
            throw new ArgumentException($"TS text may be at most {MaxTextLength} characters; it has {text.Length}.", nameof(text));
        }

        _text = SafeText.ToAscii(text, nameof(text));
        Text = text;
    }

    /// <summary>The text to echo.</summary>
    public string Text { get; }

    /// <summary>Creates the command from received text, as the PLC takes it: any characters, echoed unchanged.</summary>
    private TestCommand(byte[] received)
    {
        _text = received;
        Text = System.Text.Encoding.ASCII.GetString(received);
    }

    /// <inheritdoc/>
    public override CModeCommandRow Row => CommandRow;

    /// <summary>TS: TEST. The echo carries no end code; any text up to the longest a TS may carry.</summary>
    internal static CModeCommandRow CommandRow { get; } = new("TS", "TEST", CommandEffect.ReadOnly, MaxTextLength)
    {
        AnswerHasEndCode = false,
        Parse = static text => text.Length > MaxTextLength
            ? throw CModeCommandParser.Reject(EndCode.FrameLengthError, "TS text is too long.")
            : new TestCommand(text.ToArray()),
        Execute = static (command, _, _) => CModeReply.Echo(((TestCommand)command)._text),
        DescribeCommand = static (command, fields) => fields.Field("text", ((TestCommand)command).Text),
    };

    /// <inheritdoc/>
    public override int TextLength => _text.Length;

    /// <inheritdoc/>
    public override int ResponseAtomLength => 1;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => _text.CopyTo(destination);

    /// <summary>Writes the unframed message of a TS carrying <paramref name="text"/> without a command object (the link's resynchronisation fence).</summary>
    /// <returns>The number of characters written.</returns>
    internal static int WriteMessage(int unit, ReadOnlySpan<byte> text, Span<byte> destination)
    {
        MessagePrefix.Write(destination, unit, CommandRow.Header);
        text.CopyTo(destination.Slice(PrefixLength));
        return PrefixLength + text.Length;
    }
}
