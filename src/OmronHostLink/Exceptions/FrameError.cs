namespace OmronHostLink;

/// <summary>Why a received frame was refused.</summary>
public enum FrameError
{
    /// <summary>The FCS characters do not match the frame.</summary>
    BadFcs,

    /// <summary>The frame came from another unit number than the one addressed.</summary>
    WrongUnit,

    /// <summary>The header does not echo the command's header.</summary>
    WrongHeader,

    /// <summary>The frame's shape is wrong: missing parts, wrong characters, wrong ending.</summary>
    Malformed,

    /// <summary>The response holds fewer (or more) data characters than the command asked for.</summary>
    WrongLength,

    /// <summary>More characters arrived without a CR than any frame may hold.</summary>
    TooLong,

    /// <summary>The link was in the middle of another exchange's frames, or the PLC sent a frame nobody asked for.</summary>
    Unexpected,

    /// <summary>
    /// The frame cannot be the answer to the command just sent: it was complete before that command and its answer could
    /// have crossed the line, or (with <see cref="HostLinkClientOptions.VerifyAnswers"/>) another frame came between the
    /// answer and the check sent behind it. A late answer to an earlier command, delivered out of turn.
    /// </summary>
    Stale,
}
