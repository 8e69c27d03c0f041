namespace OmronHostLink.Cli;

/// <summary>
/// How <c>write --as string</c> lays text into words, two characters a word, high byte first, so that a shorter text
/// never leaves the end of an older one behind.
/// </summary>
/// <remarks>
/// Without a field length the text is written the way Omron's string instructions store strings: followed by NUL (in
/// the last word's low byte for an odd length, as a 0000 word after it for an even length), so every reader that stops
/// at NUL sees exactly the text. With <c>--length N</c> the whole N-character field is written, the text padded with
/// NUL or, with <c>--pad space</c>, with spaces (fixed-width fields of displays that do not stop at NUL).
/// </remarks>
internal sealed class StringWrite
{
    private StringWrite(string text, ushort[] words, string layout)
    {
        Text = text;
        Words = words;
        Layout = layout;
    }

    public string Text { get; }

    public ushort[] Words { get; }

    /// <summary>How the words were filled, for the summary: "and NUL", "12-character field, padded with spaces".</summary>
    public string Layout { get; }

    /// <summary>Checks and lays out the text (nothing is sent when it is refused).</summary>
    /// <param name="text">The text.</param>
    /// <param name="length">The field width in characters (<c>--length</c>), or null for NUL-terminated text.</param>
    /// <param name="spaces">Pad with spaces instead of NUL (<c>--pad space</c>; needs a field width).</param>
    public static StringWrite Create(string text, int? length, bool spaces)
    {
        if (text.Any(c => c > 0x7F))
        {
            throw new UsageException("The text must be ASCII.");
        }

        if (text.Contains('\0', StringComparison.Ordinal))
        {
            throw new UsageException("The text may not contain NUL: NUL ends a string in the PLC.");
        }

        if (length is null && spaces)
        {
            throw new UsageException("--pad space fills a fixed-width field: give its width in characters with --length N.");
        }

        if (length is { } n && text.Length > n)
        {
            throw new UsageException($"The text is {text.Length} characters; it does not fit --length {n}.");
        }

        int characters = length ?? text.Length + 1;
        var bytes = new byte[characters + (characters % 2)];
        if (spaces)
        {
            Array.Fill(bytes, (byte)' ', 0, characters);
        }

        for (int i = 0; i < text.Length; i++)
        {
            bytes[i] = (byte)text[i];
        }

        var words = new ushort[bytes.Length / 2];
        for (int i = 0; i < words.Length; i++)
        {
            words[i] = (ushort)((bytes[2 * i] << 8) | bytes[(2 * i) + 1]);
        }

        string layout = length is { } width
            ? $"{width}-character field{(text.Length == width ? "" : spaces ? ", padded with spaces" : ", padded with NUL")}"
            : "and NUL";
        return new StringWrite(text, words, layout);
    }
}
