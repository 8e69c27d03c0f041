namespace OmronHostLink.Protocol.CMode;

/// <summary>MS: STATUS READ. The answer holds the status word and, when one is active, the FAL/FALS message.</summary>
internal sealed class StatusReadCommand : CModeCommand
{
    /// <summary>The one instance (the command has no parameters).</summary>
    public static StatusReadCommand Instance { get; } = new();

    /// <inheritdoc/>
    public override string Header => CModeHeaders.StatusRead;

    /// <inheritdoc/>
    public override int TextLength => 0;

    /// <summary>End code, status word (4) and the FAL/FALS message (16).</summary>
    internal override int MaxAnswerTextLength => CModeResponse.EndCodeLength + 4 + 16;

    /// <inheritdoc/>
    internal override CommandEffect Effect => CommandEffect.ReadOnly;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
    }
}

/// <summary>MM: PLC MODEL READ.</summary>
internal sealed class ModelReadCommand : CModeCommand
{
    /// <summary>The one instance.</summary>
    public static ModelReadCommand Instance { get; } = new();

    /// <inheritdoc/>
    public override string Header => CModeHeaders.ModelRead;

    /// <inheritdoc/>
    public override int TextLength => 0;

    /// <summary>End code and the model code (2).</summary>
    internal override int MaxAnswerTextLength => CModeResponse.EndCodeLength + 2;

    /// <inheritdoc/>
    internal override CommandEffect Effect => CommandEffect.ReadOnly;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
    }
}

/// <summary>KC: FORCED SET/RESET CANCEL (cancels every forced bit).</summary>
internal sealed class ForcedCancelCommand : CModeCommand
{
    /// <summary>The one instance.</summary>
    public static ForcedCancelCommand Instance { get; } = new();

    /// <inheritdoc/>
    public override string Header => CModeHeaders.ForcedSetResetCancel;

    /// <inheritdoc/>
    public override int TextLength => 0;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
    }
}

/// <summary>XZ: ABORT. Stops the Host Link exchange in progress; the PLC sends no answer.</summary>
internal sealed class AbortCommand : CModeCommand
{
    /// <summary>The one instance.</summary>
    public static AbortCommand Instance { get; } = new();

    /// <inheritdoc/>
    public override string Header => CModeHeaders.Abort;

    /// <inheritdoc/>
    public override int TextLength => 0;

    /// <inheritdoc/>
    public override bool ExpectsResponse => false;

    /// <inheritdoc/>
    internal override int MaxAnswerTextLength => 0;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination)
    {
    }
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
    public override string Header => CModeHeaders.StatusChange;

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
    public override string Header => CModeHeaders.ErrorRead;

    /// <inheritdoc/>
    public override int TextLength => 2;

    /// <summary>End code and two error words (8).</summary>
    internal override int MaxAnswerTextLength => CModeResponse.EndCodeLength + 8;

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

    /// <inheritdoc/>
    public override string Header => CModeHeaders.Test;

    /// <inheritdoc/>
    public override int TextLength => _text.Length;

    /// <inheritdoc/>
    public override int ResponseAtomLength => 1;

    /// <summary>The echo carries no end code; any text up to the longest a TS may carry.</summary>
    internal override int MaxAnswerTextLength => MaxTextLength;

    /// <inheritdoc/>
    internal override CommandEffect Effect => CommandEffect.ReadOnly;

    /// <inheritdoc/>
    public override void WriteText(Span<byte> destination) => _text.CopyTo(destination);

    /// <summary>Writes the unframed message of a TS carrying <paramref name="text"/> without a command object (the link's resynchronisation fence).</summary>
    /// <returns>The number of characters written.</returns>
    internal static int WriteMessage(int unit, ReadOnlySpan<byte> text, Span<byte> destination)
    {
        MessagePrefix.Write(destination, unit, CModeHeaders.Test);
        text.CopyTo(destination.Slice(PrefixLength));
        return PrefixLength + text.Length;
    }
}
