namespace OmronHostLink;

// ASCII text: two characters a word, the first in the high byte ("AB" → 0x4142), NUL-padded, as PLC string instructions store it.
public static partial class PlcWords
{
    /// <summary>The number of words that hold <paramref name="length"/> ASCII characters: half, rounded up.</summary>
    /// <param name="length">The number of characters, 0 or more.</param>
    /// <returns>The number of words.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="length"/> is negative.</exception>
    public static int WordsForString(int length)
    {
        if (length < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(length), length, $"A string length cannot be negative; it was {length}.");
        }

        return (length / 2) + (length & 1);
    }

    /// <summary>Packs ASCII text into words, two characters a word, high byte first; an odd length ends with a NUL byte.</summary>
    /// <param name="text">ASCII text (U+0000–U+007F).</param>
    /// <param name="dest">At least <see cref="WordsForString(int)"/> words; words after those are left untouched.</param>
    /// <returns>The number of words written.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is <see langword="null"/>.</exception>
    /// <exception cref="ArgumentException">The text has a non-ASCII character, or <paramref name="dest"/> is too short; nothing is written.</exception>
    public static int WriteString(string text, Span<ushort> dest)
    {
        Guard.NotNull(text);
        CheckAscii(text);
        var words = WordsForString(text.Length);
        if (dest.Length < words)
        {
            throw new ArgumentException($"{text.Length} characters need {words} words but the span holds {dest.Length}.", nameof(dest));
        }

        for (var w = 0; w < words; w++)
        {
            var high = text[2 * w];
            var low = (2 * w) + 1 < text.Length ? text[(2 * w) + 1] : '\0';
            dest[w] = (ushort)((high << 8) | low);
        }

        return words;
    }

    /// <summary>Packs ASCII text into a new word array: "HELLO" → [0x4845, 0x4C4C, 0x4F00].</summary>
    /// <param name="text">ASCII text (U+0000–U+007F).</param>
    /// <returns><see cref="WordsForString(int)"/> words.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is <see langword="null"/>.</exception>
    /// <exception cref="ArgumentException">The text has a non-ASCII character.</exception>
    public static ushort[] FromString(string text)
    {
        Guard.NotNull(text);
        var words = new ushort[WordsForString(text.Length)];
        WriteString(text, words);
        return words;
    }

    /// <summary>Unpacks ASCII text, two characters a word, high byte first, up to the first NUL byte (or the end).</summary>
    /// <param name="words">The words.</param>
    /// <returns>The text before the first NUL.</returns>
    /// <exception cref="FormatException">A byte before the first NUL is above 0x7F, so the words are not ASCII text.</exception>
    public static string ReadString(ReadOnlySpan<ushort> words) => ReadString(words, words.Length * 2);

    /// <summary>Unpacks at most <paramref name="maxLength"/> characters; see <see cref="ReadString(ReadOnlySpan{ushort})"/>.</summary>
    /// <exception cref="FormatException">A byte of the text is above 0x7F.</exception>
    internal static string ReadString(ReadOnlySpan<ushort> words, int maxLength)
    {
        if (TryReadString(words, maxLength, out var text, out var badAt))
        {
            return text;
        }

        var word = words[badAt / 2];
        throw new FormatException(
            $"Word {badAt / 2} (0x{word:X4}) holds byte 0x{ByteAt(words, badAt):X2}, which is not ASCII; text must be 0x00–0x7F.");
    }

    /// <summary>
    /// Unpacks at most <paramref name="maxLength"/> characters up to the first NUL; false with the position of the
    /// first byte above 0x7F when the words are not ASCII text.
    /// </summary>
    internal static bool TryReadString(ReadOnlySpan<ushort> words, int maxLength, out string text, out int nonAsciiAt)
    {
        // First pass: find the length and check every byte, so the string is built once at its final size.
        var limit = Math.Min(maxLength, words.Length * 2);
        var length = 0;
        while (length < limit)
        {
            var b = ByteAt(words, length);
            if (b == 0)
            {
                break;
            }

            if (b > 0x7F)
            {
                text = string.Empty;
                nonAsciiAt = length;
                return false;
            }

            length++;
        }

        nonAsciiAt = -1;
        if (length == 0)
        {
            text = string.Empty;
            return true;
        }

        var chars = length <= 256 ? stackalloc char[length] : new char[length];
        for (var i = 0; i < length; i++)
        {
            chars[i] = (char)ByteAt(words, i);
        }

#if NET
        text = new string(chars);
#else
        text = new string(chars.ToArray());
#endif
        return true;
    }

    private static int ByteAt(ReadOnlySpan<ushort> words, int index) =>
        (index & 1) == 0 ? words[index / 2] >> 8 : words[index / 2] & 0xFF;

    private static void CheckAscii(string text)
    {
        for (var i = 0; i < text.Length; i++)
        {
            if (text[i] > 0x7F)
            {
                throw new ArgumentException(
                    $"'{text[i]}' (U+{(int)text[i]:X4}) at position {i} is not ASCII; PLC text holds characters U+0000–U+007F only.",
                    nameof(text));
            }
        }
    }
}
