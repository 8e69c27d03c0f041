using System.Text;

namespace OmronHostLink.Capture;

/// <summary>What a recorder reads off a frame's first characters, for its records.</summary>
internal static class CaptureText
{
    /// <summary>The two header characters of a first frame (<c>@00RD…</c> gives <c>RD</c>; <c>@**</c> gives <c>**</c>), or null.</summary>
    public static string? HeaderOf(ReadOnlySpan<byte> frame)
    {
        if (frame.Length >= 3 && frame[0] == (byte)'@' && frame[1] == (byte)'*' && frame[2] == (byte)'*')
        {
            return "**";
        }

        if (frame.Length < 6 || frame[0] != (byte)'@' || !Printable(frame[3]) || !Printable(frame[4]) || frame[3] == (byte)'\r' || frame[4] == (byte)'\r')
        {
            return null;
        }

        return Encoding.ASCII.GetString(frame.Slice(3, 2).ToArray());
    }

    private static bool Printable(byte b) => b is >= 0x20 and <= 0x7E;
}
