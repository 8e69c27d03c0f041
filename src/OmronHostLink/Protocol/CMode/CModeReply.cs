namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// What a PLC answers to one C-mode command, before framing: the answer's text after the header (sub-header, end code,
/// data) and how it may be cut into frames. Null where the PLC sends no answer (XZ).
/// </summary>
internal sealed class CModeReply
{
    private CModeReply(byte[] text, int fixedText, int atomLength, int maxContinuationText, bool undefined)
    {
        Text = text;
        FixedText = fixedText;
        AtomLength = atomLength;
        MaxContinuationText = maxContinuationText;
        IsUndefined = undefined;
    }

    /// <summary>The answer's text after the header: sub-header (QQ), end code, data; for TS the echo.</summary>
    public byte[] Text { get; }

    /// <summary>Characters at the start of the text that stay in the first frame (sub-header and end code).</summary>
    public int FixedText { get; }

    /// <summary>Characters of one data entry, never split between frames.</summary>
    public int AtomLength { get; }

    /// <summary>The most text a later frame carries when the PLC stops short of the frame limit (RG); 0 for none.</summary>
    public int MaxContinuationText { get; }

    /// <summary>The IC answer: the PLC does not execute the header.</summary>
    public bool IsUndefined { get; }

    /// <summary>The IC answer (no end code, no text).</summary>
    public static CModeReply Undefined { get; } = new([], 0, 1, 0, undefined: true);

    /// <summary>An answer carrying an end code (and the sub-header before it, for QQ) and nothing else.</summary>
    public static CModeReply EndCodeOnly(EndCode code, string? subHeader = null)
        => Ok(code, subHeader, default);

    /// <summary>An answer: sub-header (QQ only), end code, data.</summary>
    public static CModeReply Ok(EndCode code, string? subHeader, ReadOnlySpan<byte> data, int atomLength = 4, int maxContinuationText = 0)
    {
        int sub = subHeader?.Length ?? 0;
        var text = new byte[sub + CModeResponse.EndCodeLength + data.Length];
        for (int i = 0; i < sub; i++)
        {
            text[i] = (byte)subHeader![i];
        }

        HexAscii.WriteByte((byte)code, text.AsSpan(sub, CModeResponse.EndCodeLength));
        data.CopyTo(text.AsSpan(sub + CModeResponse.EndCodeLength));
        return new CModeReply(text, sub + CModeResponse.EndCodeLength, atomLength, maxContinuationText, undefined: false);
    }

    /// <summary>An answer without an end code (the TS echo): the text as given, cut anywhere.</summary>
    public static CModeReply Echo(ReadOnlySpan<byte> text) => new(text.ToArray(), 0, 1, 0, undefined: false);
}
