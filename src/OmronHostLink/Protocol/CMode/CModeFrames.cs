namespace OmronHostLink.Protocol.CMode;

/// <summary>Fixed C-mode transmissions.</summary>
internal static class CModeFrames
{
    /// <summary>INITIALIZE: <c>@**</c>CR. No unit, no FCS, no answer: resets the Host Link transmission control of every unit on the line.</summary>
    public static ReadOnlySpan<byte> Initialize => "@**\r"u8;

    /// <summary>Whether <paramref name="frame"/> is INITIALIZE (<c>@**</c>, whatever follows).</summary>
    public static bool IsInitialize(ReadOnlySpan<byte> frame) => frame.StartsWith(Initialize.Slice(0, 3));

    /// <summary>A bare CR: the delimiter a host sends for the next response frame, and the PLC's answer to a non-final command frame.</summary>
    public static ReadOnlySpan<byte> Delimiter => "\r"u8;
}
