namespace OmronHostLink.Simulator.Protocol;

/// <summary>What the PLC sends after receiving one frame: nothing, the bare CR of the command handshake, or one answer frame.</summary>
internal readonly struct LinkReply
{
    private LinkReply(byte[]? bytes, bool isHandshake, TimeSpan delay = default)
    {
        Bytes = bytes;
        IsHandshake = isHandshake;
        Delay = delay;
    }

    /// <summary>Silence.</summary>
    public static LinkReply None => default;

    /// <summary>The bare CR that asks the host for the next command frame.</summary>
    public static LinkReply Handshake => new("\r"u8.ToArray(), true);

    /// <summary>The bytes to send, or null for silence.</summary>
    public byte[]? Bytes { get; }

    /// <summary>Whether the bytes are the bare CR handshake (never faulted).</summary>
    public bool IsHandshake { get; }

    /// <summary>Extra time to wait before sending (FINS response wait time), on top of the turnaround.</summary>
    public TimeSpan Delay { get; }

    /// <summary>One answer frame.</summary>
    public static LinkReply Frame(byte[] frame, TimeSpan delay = default) => new(frame, false, delay);
}
