using System.Buffers;

namespace OmronHostLink.Protocol;

/// <summary>
/// Splits an unframed Host Link message (<c>@</c> + unit + header + text) into frames and writes each frame with its
/// FCS and its ending: <c>*</c>CR on the last (or only) frame, a bare CR (delimiter) on every other frame.
/// </summary>
/// <remarks>
/// Limits (W342): a first or single frame holds at most 131 characters, a later frame at most 128, counting FCS and ending.
/// The first <c>fixedLength</c> characters (address fields, end code) must stay in the first frame, and the rest is
/// cut only between whole atoms (four characters of one word), so no word is ever split across frames.
/// </remarks>
internal static class FrameWriter
{
    /// <summary>Longest first (or single) frame, including FCS and ending.</summary>
    public const int MaxFirstFrameLength = 131;

    /// <summary>Longest continuation frame, including FCS and ending.</summary>
    public const int MaxContinuationFrameLength = 128;

    /// <summary>Characters that follow the text of a final frame: FCS, <c>*</c>, CR.</summary>
    public const int FinalOverhead = 4;

    /// <summary>Characters that follow the text of a non-final frame: FCS, CR.</summary>
    public const int DelimiterOverhead = 3;

    /// <summary>
    /// How many characters of the remaining message go into the next frame.
    /// </summary>
    /// <param name="remaining">Characters of the message not yet framed.</param>
    /// <param name="first">Whether this is the first frame (it then also holds <paramref name="fixedLength"/>).</param>
    /// <param name="fixedLength">Characters at the start of the message that must stay whole in the first frame.</param>
    /// <param name="atomLength">Size of the units the rest may be cut between (4 for word data, 1 for free text).</param>
    /// <param name="final">Whether the frame is the last one.</param>
    /// <exception cref="ArgumentException">The fixed part or one atom does not fit in a frame.</exception>
    public static int NextSegmentLength(int remaining, bool first, int fixedLength, int atomLength, out bool final)
    {
        int limit = first ? MaxFirstFrameLength : MaxContinuationFrameLength;
        if (remaining + FinalOverhead <= limit)
        {
            final = true;
            return remaining;
        }

        final = false;
        int room = limit - DelimiterOverhead;
        int head = first ? fixedLength : 0;
        int atoms = (room - head) / atomLength;
        if (atoms <= 0 || head > room)
        {
            throw new ArgumentException("The fixed part of the message or one data unit does not fit in a Host Link frame.");
        }

        return head + (atoms * atomLength);
    }

    /// <summary>Number of frames the message will take.</summary>
    public static int CountFrames(int messageLength, int fixedLength, int atomLength)
    {
        int frames = 0;
        int remaining = messageLength;
        bool first = true;
        bool final;
        do
        {
            remaining -= NextSegmentLength(remaining, first, fixedLength, atomLength, out final);
            first = false;
            frames++;
        }
        while (!final);

        return frames;
    }

    /// <summary>Total characters on the wire for the message, all frames included.</summary>
    public static int WireLength(int messageLength, int fixedLength, int atomLength)
    {
        int frames = CountFrames(messageLength, fixedLength, atomLength);
        return messageLength + ((frames - 1) * DelimiterOverhead) + FinalOverhead;
    }

    /// <summary>Writes one frame: the segment, its FCS, and its ending.</summary>
    /// <returns>The number of characters written.</returns>
    public static int WriteFrame(ReadOnlySpan<byte> segment, bool final, Span<byte> destination)
    {
        int length = segment.Length + (final ? FinalOverhead : DelimiterOverhead);
        if (destination.Length < length)
        {
            throw new ArgumentException("The destination is too small for the frame.", nameof(destination));
        }

        segment.CopyTo(destination);
        Fcs.Write(segment, destination.Slice(segment.Length, 2));
        int i = segment.Length + 2;
        if (final)
        {
            destination[i++] = (byte)'*';
        }

        destination[i++] = (byte)'\r';
        return i;
    }

    /// <summary>Writes one frame to <paramref name="writer"/>.</summary>
    public static void WriteFrame(IBufferWriter<byte> writer, ReadOnlySpan<byte> segment, bool final)
    {
        Guard.NotNull(writer);
        Span<byte> span = writer.GetSpan(segment.Length + FinalOverhead);
        writer.Advance(WriteFrame(segment, final, span));
    }

    /// <summary>
    /// Writes every frame of <paramref name="message"/> back to back (the form a capture shows, without the
    /// handshakes between frames).
    /// </summary>
    /// <returns>The number of frames written.</returns>
    public static int WriteFrames(IBufferWriter<byte> writer, ReadOnlySpan<byte> message, int fixedLength, int atomLength)
    {
        Guard.NotNull(writer);
        int frames = 0;
        bool first = true;
        bool final;
        do
        {
            int length = NextSegmentLength(message.Length, first, fixedLength, atomLength, out final);
            WriteFrame(writer, message.Slice(0, length), final);
            message = message.Slice(length);
            first = false;
            frames++;
        }
        while (!final);

        return frames;
    }

    /// <summary>Writes an unpartitioned frame of any length (FINS over Host Link frames are never split).</summary>
    public static void WriteSingleFrame(IBufferWriter<byte> writer, ReadOnlySpan<byte> message)
        => WriteFrame(writer, message, final: true);
}
