using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Cli;

/// <summary>
/// <c>explain</c>'s side of decoding a frame: what the user typed turned into the frame's bytes, then explained by the
/// library's <see cref="Protocol.Explain.FrameExplainer"/> (the same explanation the gateway's line trace shows).
/// </summary>
internal static class FrameExplainer
{
    /// <summary>Turns what the user typed into frame bytes: a literal <c>\r</c> becomes CR; surrounding whitespace and a trailing LF go.</summary>
    public static byte[] Normalise(string input)
    {
        string s = input.Replace("\\r", "\r", StringComparison.Ordinal).Replace("\\n", "\n", StringComparison.Ordinal);
        s = s.Trim(' ', '\t', '\n');
        var bytes = new byte[s.Length];
        for (int i = 0; i < s.Length; i++)
        {
            if (s[i] > 0x7E && s[i] != '\r')
            {
                throw new UsageException($"The frame holds the non-ASCII character '{s[i]}' at position {i}; a Host Link frame is ASCII.");
            }

            bytes[i] = (byte)s[i];
        }

        if (bytes.Length == 0)
        {
            throw new UsageException("The frame is empty.");
        }

        return bytes;
    }

    /// <summary>Explains one typed frame with the standard command tables.</summary>
    /// <param name="input">The frame as the user typed it.</param>
    /// <param name="response">True for an answer, false for a command, null to tell from the frame where it can.</param>
    public static FrameExplanation Explain(string input, bool? response) => Explain(input, response, CModeCommandTable.Standard);

    /// <summary>Explains one typed frame, looking C-mode headers up in <paramref name="table"/> and FINS codes in <paramref name="fins"/> (default: the standard FINS table).</summary>
    internal static FrameExplanation Explain(string input, bool? response, CModeCommandTable table, FinsCommandTable? fins = null)
        => Protocol.Explain.FrameExplainer.Explain(Normalise(input), response, table, fins);
}
