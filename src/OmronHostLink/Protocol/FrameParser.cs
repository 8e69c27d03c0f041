namespace OmronHostLink.Protocol;

/// <summary>
/// Validates the shape and FCS of single frames. Every failure is a <see cref="HostLinkFrameException"/>: a damaged
/// frame never yields text.
/// </summary>
public static class FrameParser
{
    /// <summary>The shortest first frame: <c>@</c>, unit, header, FCS, <c>*</c>, CR.</summary>
    public const int MinFirstFrameLength = 9;

    /// <summary>Validates a first (or single) frame: <c>@</c> + two-digit unit + header + text + FCS + ending.</summary>
    /// <exception cref="HostLinkFrameException">The frame is malformed or its FCS does not match.</exception>
    public static FrameInfo ParseFirst(ReadOnlySpan<byte> frame)
    {
        if (frame.Length < MinFirstFrameLength - 1 || frame[0] != (byte)'@')
        {
            throw Malformed(frame, "it does not start with '@' and a unit number and header");
        }

        int body = BodyEnd(frame, out bool final);
        if (body < 5)
        {
            throw Malformed(frame, "it is too short to hold a unit number, a header and an FCS");
        }

        if (!HexAscii.TryParseDecimal(frame.Slice(1, 2), out int unit))
        {
            throw new HostLinkFrameException(FrameError.Malformed, $"The unit number '{FrameText.Printable(frame.Slice(1, 2))}' is not two decimal digits.", frame);
        }

        CheckFcs(frame, 0, body);
        return new FrameInfo(unit, 5, body - 5, final);
    }

    /// <summary>Validates a continuation frame: text + FCS + ending (the FCS covers that frame's text only).</summary>
    /// <exception cref="HostLinkFrameException">The frame is malformed or its FCS does not match.</exception>
    public static FrameInfo ParseContinuation(ReadOnlySpan<byte> frame)
    {
        int body = BodyEnd(frame, out bool final);
        CheckFcs(frame, 0, body);
        return new FrameInfo(-1, 0, body, final);
    }

    /// <summary>Returns where the checked characters end (the FCS starts there) and what ending the frame has.</summary>
    private static int BodyEnd(ReadOnlySpan<byte> frame, out bool final)
    {
        if (frame.Length < 3 || frame[frame.Length - 1] != (byte)'\r')
        {
            throw Malformed(frame, "it does not end with CR");
        }

        final = frame[frame.Length - 2] == (byte)'*';
        int fcsEnd = frame.Length - (final ? 2 : 1);
        int body = fcsEnd - 2;
        if (body < 0)
        {
            throw Malformed(frame, "it is too short to hold an FCS");
        }

        for (int i = 0; i < fcsEnd; i++)
        {
            byte c = frame[i];
            if (c < 0x20 || c > 0x7E)
            {
                throw Malformed(frame, $"it contains the non-printable character 0x{c:X2} at position {i}");
            }
        }

        return body;
    }

    private static void CheckFcs(ReadOnlySpan<byte> frame, int start, int end)
    {
        ReadOnlySpan<byte> found = frame.Slice(end, 2);
        if (!Fcs.Verify(frame.Slice(start, end - start), found, out byte expected))
        {
            throw new HostLinkFrameException(
                FrameError.BadFcs,
                $"FCS error: the frame carries '{FrameText.Printable(found)}' but its characters give '{expected:X2}'.",
                frame);
        }
    }

    private static HostLinkFrameException Malformed(ReadOnlySpan<byte> frame, string why)
        => new(FrameError.Malformed, $"The frame is malformed: {why}.", frame);
}
