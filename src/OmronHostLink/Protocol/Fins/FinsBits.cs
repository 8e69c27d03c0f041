namespace OmronHostLink.Protocol.Fins;

/// <summary>Bit data of FINS read responses and write commands: one byte per bit, 00 (OFF) or 01 (ON).</summary>
internal static class FinsBits
{
    /// <summary>Decodes exactly <paramref name="count"/> bits.</summary>
    /// <exception cref="HostLinkFrameException">
    /// <see cref="FrameError.WrongLength"/> when the data is not exactly <paramref name="count"/> bytes;
    /// <see cref="FrameError.Malformed"/> when a byte is neither 00 nor 01.
    /// </exception>
    public static bool[] Read(ReadOnlySpan<byte> data, int count)
    {
        if (count < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, "The bit count cannot be negative.");
        }

        var bits = new bool[count];
        Read(data, bits);
        return bits;
    }

    /// <summary>Decodes exactly <paramref name="destination"/>.Length bits.</summary>
    /// <exception cref="HostLinkFrameException">Wrong length, or a byte that is neither 00 nor 01.</exception>
    public static void Read(ReadOnlySpan<byte> data, Span<bool> destination)
    {
        if (data.Length != destination.Length)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The response carries {data.Length} data bytes; {destination.Length} bits need exactly {destination.Length}.");
        }

        for (int i = 0; i < data.Length; i++)
        {
            destination[i] = data[i] switch
            {
                0 => false,
                1 => true,
                _ => throw new HostLinkFrameException(FrameError.Malformed, $"Bit {i} of the response is {data[i]:X2}; bits are 00 or 01."),
            };
        }
    }

    /// <summary>Encodes bits, one byte each; <paramref name="destination"/> must hold one byte per bit.</summary>
    public static void Write(ReadOnlySpan<bool> bits, Span<byte> destination)
    {
        if (destination.Length < bits.Length)
        {
            throw new ArgumentException("The destination is too small for the bits.", nameof(destination));
        }

        for (int i = 0; i < bits.Length; i++)
        {
            destination[i] = bits[i] ? (byte)1 : (byte)0;
        }
    }

    /// <summary>Encodes bits into a new array.</summary>
    public static byte[] ToBytes(ReadOnlySpan<bool> bits)
    {
        var bytes = new byte[bits.Length];
        Write(bits, bytes);
        return bytes;
    }
}
