using System.Buffers;

namespace OmronHostLink.Protocol;

/// <summary>What <see cref="FrameReader.TryReadFrame"/> found in the buffer.</summary>
internal enum FrameScanResult
{
    /// <summary>A CR-terminated frame was taken from the buffer.</summary>
    Frame,

    /// <summary>No complete frame yet; read more and try again.</summary>
    NeedMoreData,

    /// <summary>More than <see cref="FrameReader.MaxFrameLength"/> characters arrived without a CR: the data is not a frame.</summary>
    Overflow,
}

/// <summary>
/// Cuts CR-terminated frames out of received bytes, in any fragmentation. Before a first frame, anything ahead of
/// <c>@</c> is line noise and is discarded. Nothing is buffered without bound: past
/// <see cref="MaxFrameLength"/> characters without a CR the reader reports <see cref="FrameScanResult.Overflow"/>.
/// </summary>
internal static class FrameReader
{
    /// <summary>
    /// The longest run of characters accepted before a CR. FINS over Host Link frames reach 1,115 characters; a CS/CJ
    /// serial unit discards anything longer than its 1,200-byte reception buffer, and so does this reader.
    /// </summary>
    public const int MaxFrameLength = 1200;

    /// <summary>
    /// Takes the next frame (including its CR) from the start of <paramref name="buffer"/>.
    /// </summary>
    /// <param name="buffer">Received bytes; on return, what is left after the frame and any discarded noise.</param>
    /// <param name="expectStart">True when the next frame must be a first frame (starting with <c>@</c>): bytes before the <c>@</c> are discarded.</param>
    /// <param name="frame">The frame, valid until the buffer is consumed.</param>
    /// <param name="discarded">How many noise bytes were dropped.</param>
    public static FrameScanResult TryReadFrame(ref ReadOnlySequence<byte> buffer, bool expectStart, out ReadOnlySequence<byte> frame, out long discarded)
    {
        frame = default;
        discarded = 0;
        if (expectStart)
        {
            SequencePosition? at = buffer.PositionOf((byte)'@');
            if (at is null)
            {
                discarded = buffer.Length;
                buffer = buffer.Slice(buffer.End);
                return FrameScanResult.NeedMoreData;
            }

            ReadOnlySequence<byte> noise = buffer.Slice(0, at.Value);
            discarded = noise.Length;
            buffer = buffer.Slice(at.Value);
        }

        SequencePosition? cr = buffer.PositionOf((byte)'\r');
        if (cr is null)
        {
            return buffer.Length > MaxFrameLength ? FrameScanResult.Overflow : FrameScanResult.NeedMoreData;
        }

        SequencePosition end = buffer.GetPosition(1, cr.Value);
        if (expectStart)
        {
            // '@' never appears inside a frame, so an earlier '@' belongs to a frame cut short (truncated, or
            // interrupted by noise): start at the last one before the CR and drop the cut frame as noise.
            long lastAt = LastIndexOf(buffer.Slice(0, cr.Value), (byte)'@');
            if (lastAt > 0)
            {
                discarded += lastAt;
                buffer = buffer.Slice(lastAt);
                end = buffer.GetPosition(1, buffer.PositionOf((byte)'\r')!.Value);
            }
        }

        frame = buffer.Slice(0, end);
        if (frame.Length > MaxFrameLength + 1)
        {
            buffer = buffer.Slice(end);
            return FrameScanResult.Overflow;
        }

        buffer = buffer.Slice(end);
        return FrameScanResult.Frame;
    }

    private static long LastIndexOf(ReadOnlySequence<byte> sequence, byte value)
    {
        long result = -1;
        long offset = 0;
        foreach (ReadOnlyMemory<byte> segment in sequence)
        {
            int i = segment.Span.LastIndexOf(value);
            if (i >= 0)
            {
                result = offset + i;
            }

            offset += segment.Length;
        }

        return result;
    }
}
