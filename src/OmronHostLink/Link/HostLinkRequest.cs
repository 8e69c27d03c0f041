namespace OmronHostLink.Link;

/// <summary>One command for the link to carry: its unframed message and how it may be framed and answered.</summary>
internal readonly struct HostLinkRequest
{
    public HostLinkRequest(int unit, string header, ReadOnlyMemory<byte> message, int fixedLength, int atomLength, bool multiFrame, bool expectsResponse, int maxResponseText, bool retryable, bool singleFrameOnly = false)
    {
        Unit = unit;
        Header = header;
        Message = message;
        FixedLength = fixedLength;
        AtomLength = atomLength;
        MultiFrame = multiFrame;
        ExpectsResponse = expectsResponse;
        MaxResponseText = maxResponseText;
        Retryable = retryable;
        SingleFrameOnly = singleFrameOnly;
    }

    public int Unit { get; }

    /// <summary>The two header characters the answer must echo.</summary>
    public string Header { get; }

    /// <summary><c>@</c> + unit + header + text, unframed.</summary>
    public ReadOnlyMemory<byte> Message { get; }

    /// <summary>Characters of the message that must stay in the first frame.</summary>
    public int FixedLength { get; }

    /// <summary>Units the rest of the message may be cut between.</summary>
    public int AtomLength { get; }

    /// <summary>Whether the command may span frames (area writes).</summary>
    public bool MultiFrame { get; }

    /// <summary>Whether the PLC answers (XZ: no).</summary>
    public bool ExpectsResponse { get; }

    /// <summary>The most response text (end code + data, all frames) the answer may hold; more is a frame error.</summary>
    public int MaxResponseText { get; }

    /// <summary>Whether a failed attempt may be repeated.</summary>
    public bool Retryable { get; }

    /// <summary>FINS frames: one frame of any length, never partitioned.</summary>
    public bool SingleFrameOnly { get; }
}
