namespace OmronHostLink.Protocol.Fins;

/// <summary>Word data of FINS read responses and write commands: 2 bytes per word, most significant byte first.</summary>
internal static class FinsWords
{
    /// <summary>Decodes exactly <paramref name="count"/> words.</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: the data is not exactly <paramref name="count"/> × 2 bytes.</exception>
    public static ushort[] Read(ReadOnlySpan<byte> data, int count)
    {
        if (count < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, "The word count cannot be negative.");
        }

        var words = new ushort[count];
        Read(data, words);
        return words;
    }

    /// <summary>Decodes exactly <paramref name="destination"/>.Length words.</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: the data is not exactly 2 bytes per word.</exception>
    public static void Read(ReadOnlySpan<byte> data, Span<ushort> destination)
    {
        if (data.Length != destination.Length * 2)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The response carries {data.Length} data bytes; {destination.Length} words need exactly {destination.Length * 2}.");
        }

        for (int i = 0; i < destination.Length; i++)
        {
            destination[i] = FinsBytes.ReadUInt16(data, i * 2);
        }
    }

    /// <summary>Encodes words, 2 bytes each; <paramref name="destination"/> must hold 2 × words bytes.</summary>
    public static void Write(ReadOnlySpan<ushort> words, Span<byte> destination)
    {
        if (destination.Length < words.Length * 2)
        {
            throw new ArgumentException("The destination is too small for the words.", nameof(destination));
        }

        for (int i = 0; i < words.Length; i++)
        {
            FinsBytes.WriteUInt16(destination, i * 2, words[i]);
        }
    }

    /// <summary>Encodes words into a new array.</summary>
    public static byte[] ToBytes(ReadOnlySpan<ushort> words)
    {
        var bytes = new byte[words.Length * 2];
        Write(words, bytes);
        return bytes;
    }
}
