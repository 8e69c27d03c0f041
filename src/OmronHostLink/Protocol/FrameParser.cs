namespace OmronHostLink.Protocol;

/// <summary>
/// Validates the shape and FCS of single frames. Every failure is a <see cref="HostLinkFrameException"/>: a damaged
/// frame never yields text.
/// </summary>
internal static class FrameParser
{
    /// <summary>The shortest first frame: <c>@</c>, unit, header, FCS, <c>*</c>, CR.</summary>
    public const int MinFirstFrameLength = 9;

    /// <summary>Validates a first (or single) frame: <c>@</c> + two-digit unit + header + text + FCS + ending.</summary>
    /// <exception cref="HostLinkFrameException">The frame is malformed or its FCS does not match.</exception>
    public static FrameInfo ParseFirst(ReadOnlySpan<byte> frame)
    {
        if (frame.Length < MinFirstFrameLength - 1 || frame[0] != (byte)'@')
        {
            throw new HostLinkFrameException(FrameError.Malformed, FrameCheck.Malformed("it does not start with '@' and a unit number and header"), frame);
        }

        FrameCheck check = FrameCheck.Of(frame);
        if ((check.ShapeFault(frame) ?? check.FirstFrameFault(frame)) is { } fault)
        {
            throw new HostLinkFrameException(FrameError.Malformed, fault, frame);
        }

        ThrowIfFcsFault(frame, check);
        return new FrameInfo(check.Unit, MessagePrefix.Length, check.FirstFrameTextLength, check.IsFinal);
    }

    /// <summary>Validates a continuation frame: text + FCS + ending (the FCS covers that frame's text only).</summary>
    /// <exception cref="HostLinkFrameException">The frame is malformed or its FCS does not match.</exception>
    public static FrameInfo ParseContinuation(ReadOnlySpan<byte> frame)
    {
        FrameCheck check = FrameCheck.Of(frame);
        if (check.ShapeFault(frame) is { } fault)
        {
            throw new HostLinkFrameException(FrameError.Malformed, fault, frame);
        }

        ThrowIfFcsFault(frame, check);
        return new FrameInfo(-1, 0, check.FcsAt, check.IsFinal);
    }

    private static void ThrowIfFcsFault(ReadOnlySpan<byte> frame, FrameCheck check)
    {
        if (check.FcsFault(frame) is { } fault)
        {
            throw new HostLinkFrameException(FrameError.BadFcs, fault, frame);
        }
    }
}
