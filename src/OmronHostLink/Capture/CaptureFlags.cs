namespace OmronHostLink.Capture;

/// <summary>What a recorder knows about one record's bytes beyond the bytes themselves.</summary>
[Flags]
internal enum CaptureFlags : byte
{
    /// <summary>A frame as it crossed the line.</summary>
    None = 0,

    /// <summary>The receiving UART reported a parity, framing or overrun error on these bytes.</summary>
    LineError = 1,

    /// <summary>Bytes that do not form a frame: noise before <c>@</c>, or a run cut off without its CR.</summary>
    NotFramed = 2,
}
