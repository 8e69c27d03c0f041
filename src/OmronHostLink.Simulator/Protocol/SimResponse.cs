using OmronHostLink.Protocol;

namespace OmronHostLink.Simulator.Protocol;

/// <summary>
/// An answer the PLC sends: the unframed message (<c>@</c> + unit + header + end code + data) and how it may be cut
/// into frames when it is longer than one frame.
/// </summary>
public sealed class SimResponse
{
    /// <summary>Creates the answer.</summary>
    /// <param name="message">The unframed message.</param>
    /// <param name="fixedLength">Characters at the start that must stay in the first frame (7: <c>@uuHH</c> + end code).</param>
    /// <param name="atomLength">Characters of one data entry, never split between frames (4 for words, 1 for RG flags and text).</param>
    /// <param name="maxContinuationText">
    /// The most text characters a later frame carries, when the PLC stops short of the 128-character frame limit
    /// (RG: 124 points a frame); 0 for no limit beyond the frame length.
    /// </param>
    public SimResponse(byte[] message, int fixedLength, int atomLength, int maxContinuationText = 0)
    {
        ArgumentNullException.ThrowIfNull(message);
        Message = message;
        FixedLength = fixedLength;
        AtomLength = atomLength;
        MaxContinuationText = maxContinuationText;
    }

    /// <summary>
    /// True for an answer that is never divided into frames (FINS over Host Link, header FA), whatever its length.
    /// </summary>
    public bool IsUnsplit { get; init; }

    /// <summary>Extra time the PLC waits before answering (the FINS response wait time of the command).</summary>
    public TimeSpan Delay { get; init; }

    /// <summary>
    /// The most data characters (after <see cref="FixedLength"/>) the first frame carries, when the PLC stops short of the
    /// 131-character frame limit (a Serial Communications Unit in Host Link-compatible mode C: 29 words); 0 for the
    /// frame-length limit only. An answer with more data then continues in later frames even where one frame would hold it.
    /// </summary>
    public int MaxFirstText { get; init; }

    /// <summary>The most text characters a later frame carries; 0 for the frame-length limit only.</summary>
    public int MaxContinuationText { get; }

    /// <summary>The unframed message.</summary>
    public byte[] Message { get; }

    /// <summary>Characters that stay in the first frame.</summary>
    public int FixedLength { get; }

    /// <summary>Characters of one data entry.</summary>
    public int AtomLength { get; }

    /// <summary>The message as text (for logs and tests).</summary>
    public override string ToString() => FrameText.Printable(Message);

    /// <summary>Every frame of the answer, as sent one after another (the host asks for each later frame with a bare CR).</summary>
    /// <returns>The frames, each with FCS and ending.</returns>
    public IReadOnlyList<byte[]> ToFrames()
    {
        var frames = new List<byte[]>();
        int offset = 0;
        bool final;
        do
        {
            frames.Add(NextFrame(ref offset, out final));
        }
        while (!final);

        return frames;
    }

    /// <summary>Cuts the frame that starts at <paramref name="offset"/> and moves the offset past it.</summary>
    internal byte[] NextFrame(ref int offset, out bool final)
    {
        if (IsUnsplit)
        {
            final = true;
            var whole = new byte[Message.Length + FrameWriter.FinalOverhead];
            FrameWriter.WriteFrame(Message, final: true, whole);
            offset = Message.Length;
            return whole;
        }

        int length = FrameWriter.NextSegmentLength(Message.Length - offset, offset == 0, FixedLength, AtomLength, out final);
        if (offset == 0 && MaxFirstText > 0 && length - FixedLength > MaxFirstText)
        {
            length = FixedLength + MaxFirstText - (MaxFirstText % AtomLength);
            final = false;
        }

        if (offset > 0 && MaxContinuationText > 0 && length > MaxContinuationText)
        {
            length = MaxContinuationText - (MaxContinuationText % AtomLength);
            final = false;
        }

        var frame = new byte[length + FrameWriter.FinalOverhead];
        int written = FrameWriter.WriteFrame(Message.AsSpan(offset, length), final, frame);
        offset += length;
        return written == frame.Length ? frame : frame.AsSpan(0, written).ToArray();
    }
}
