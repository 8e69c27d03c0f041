namespace OmronHostLink.Protocol.Fins;

/// <summary>What the PLC side answers a FINS command with: the response code and the data after it.</summary>
/// <param name="EndCode">The response code (MRES SRES), without the CPU error flags the PLC adds.</param>
/// <param name="Data">The response data; empty for none.</param>
internal readonly record struct FinsReply(ushort EndCode, byte[] Data)
{
    /// <summary>Normal completion without data.</summary>
    public static FinsReply Done { get; } = new(FinsEndCodes.NormalCompletion, []);

    /// <summary>Normal completion carrying <paramref name="data"/>.</summary>
    public static FinsReply Ok(byte[] data) => new(FinsEndCodes.NormalCompletion, data);

    /// <summary>A response code without data.</summary>
    public static FinsReply Code(ushort code) => new(code, []);
}
