namespace OmronHostLink.Protocol;

/// <summary>Checks text that is copied into a frame as it is, so that it can never end or fake a frame.</summary>
internal static class SafeText
{
    /// <summary>ASCII bytes of <paramref name="text"/>, refusing anything that is not printable ASCII and the frame characters <c>*</c> and <c>@</c>.</summary>
    /// <exception cref="ArgumentException">The text holds a character that may not travel inside a frame.</exception>
    public static byte[] ToAscii(string text, string parameterName)
    {
        Guard.NotNull(text, parameterName);
        var bytes = new byte[text.Length];
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            string? why = c switch
            {
                '\r' => "CR (it would end the frame)",
                '\n' => "LF",
                '*' => "'*' (it would end the frame)",
                '@' => "'@' (it would start a new frame)",
                < ' ' => $"the control character 0x{(int)c:X2}",
                > '~' => $"the non-ASCII character '{c}'",
                _ => null,
            };
            if (why is not null)
            {
                throw new ArgumentException($"The text may not contain {why}; found at position {i}.", parameterName);
            }

            bytes[i] = (byte)c;
        }

        return bytes;
    }
}
