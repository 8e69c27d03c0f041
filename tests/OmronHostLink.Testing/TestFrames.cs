using System.Text;

namespace OmronHostLink.Testing;

/// <summary>
/// Builds frames for scripted PLCs with an FCS computed here, independently of the library's own FCS code, so that a
/// test never checks the library against itself.
/// </summary>
public static class TestFrames
{
    public static string Fcs(string characters)
    {
        int x = 0;
        foreach (char c in characters)
        {
            x ^= c;
        }

        return x.ToString("X2", System.Globalization.CultureInfo.InvariantCulture);
    }

    /// <summary>A single (final) frame: body + FCS + "*\r".</summary>
    public static string Final(string body) => body + Fcs(body) + "*\r";

    /// <summary>A non-final frame: body + FCS + "\r".</summary>
    public static string Delimited(string body) => body + Fcs(body) + "\r";

    public static byte[] Bytes(string s) => Encoding.ASCII.GetBytes(s);

    public static string Words(IEnumerable<ushort> words) => string.Concat(words.Select(w => w.ToString("X4", System.Globalization.CultureInfo.InvariantCulture)));
}
