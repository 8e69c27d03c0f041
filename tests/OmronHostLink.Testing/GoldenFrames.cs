using System.Globalization;

namespace OmronHostLink.Testing;

/// <summary>Frames taken from the golden vectors (Vectors/vectors.json) by name, for scripted-PLC tests.</summary>
public static class GoldenFrames
{
    public static string[] Frames(string name) => GoldenVectors.Get(name).Frames;

    public static string[] Rd40Frames => Frames("c_rd_multi_response_40w");

    public static string[] Wd50Frames => Frames("c_wd_multi_command_50w");

    /// <summary>The 50 words the WD vector writes, read from the vector's own text (FCS and endings stripped).</summary>
    public static ushort[] Wd50Words
    {
        get
        {
            string[] f = Wd50Frames;
            string data = f[0].Substring(9, f[0].Length - 9 - 3) + f[1].Substring(0, f[1].Length - 4);
            return Enumerable.Range(0, data.Length / 4).Select(i => ushort.Parse(data.Substring(i * 4, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture)).ToArray();
        }
    }
}
