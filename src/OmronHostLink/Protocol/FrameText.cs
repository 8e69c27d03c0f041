using System.Text;

namespace OmronHostLink.Protocol;

/// <summary>Turns frame bytes into text fit for logs and messages (CR as <c>\r</c>, other control bytes as <c>\xNN</c>).</summary>
internal static class FrameText
{
    /// <summary>A printable rendering of <paramref name="bytes"/>.</summary>
    public static string Printable(ReadOnlySpan<byte> bytes)
    {
        var sb = new StringBuilder(bytes.Length + 8);
        foreach (byte b in bytes)
        {
            switch (b)
            {
                case (byte)'\r':
                    sb.Append("\\r");
                    break;
                case (byte)'\n':
                    sb.Append("\\n");
                    break;
                case (byte)'\\':
                    sb.Append("\\\\");
                    break;
                case < 0x20 or > 0x7E:
                    sb.Append("\\x").Append(b.ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
                    break;
                default:
                    sb.Append((char)b);
                    break;
            }
        }

        return sb.ToString();
    }

    /// <summary>ASCII bytes of <paramref name="text"/>; characters outside ASCII are rejected.</summary>
    /// <exception cref="ArgumentException">The text holds a non-ASCII character.</exception>
    public static byte[] Ascii(string text)
    {
        Guard.NotNull(text);
        var bytes = new byte[text.Length];
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            if (c > 0x7E)
            {
                throw new ArgumentException($"The character '{c}' at position {i} is not ASCII.", nameof(text));
            }

            bytes[i] = (byte)c;
        }

        return bytes;
    }
}
