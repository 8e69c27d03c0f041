namespace OmronHostLink.Simulator.Faults;

/// <summary>The faults chosen for one answer frame.</summary>
internal sealed class FaultPlan
{
    public static FaultPlan None { get; } = new();

    public bool Drop { get; init; }

    /// <summary>Index of the character to change, or -1.</summary>
    public int CorruptAt { get; init; } = -1;

    /// <summary>Noise bytes to send first, or null.</summary>
    public byte[]? Noise { get; init; }

    /// <summary>Number of characters to send, or -1 for the whole frame.</summary>
    public int TruncateTo { get; init; } = -1;

    public bool Late { get; init; }

    /// <summary>Held back and sent while later commands are answered.</summary>
    public bool OutOfTurn { get; init; }

    public bool Echo { get; init; }

    /// <summary>The bytes of the frame with corruption and truncation applied.</summary>
    public byte[] Shape(byte[] frame)
    {
        byte[] result = frame;
        if (CorruptAt >= 0)
        {
            result = (byte[])frame.Clone();

            // Flipping a low bit keeps a digit a digit and a letter a letter, and always changes the FCS; it must not
            // make a character that starts or ends a frame.
            byte c = (byte)(result[CorruptAt] ^ 0x01);
            if (c is (byte)'@' or (byte)'*' or (byte)'\r')
            {
                c = (byte)(result[CorruptAt] ^ 0x02);
            }

            result[CorruptAt] = c;
        }

        if (TruncateTo >= 0)
        {
            result = result.AsSpan(0, TruncateTo).ToArray();
        }

        return result;
    }
}
