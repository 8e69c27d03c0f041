namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// A FINS response received over Host Link: the response header, the command code it answers, the response code
/// (with its relay and CPU error flags) and the response data as raw bytes.
/// </summary>
/// <remarks>
/// Text after <c>FA</c>: Host Link end code(2 characters), then in hex ICF(40 or C0) [RSV GCT DNA DA1] DA2
/// [SNA SA1] SA2 SID MRC SRC MRES SRES data. A Host Link end code other than 00 comes without a FINS part and is
/// reported as <see cref="HostLinkEndCodeException"/>. A response code of 0040 (normal completion, non-fatal CPU
/// error present) is a success: <see cref="ThrowIfError"/> accepts it and <see cref="FinsEndCode.NonFatalCpuError"/>
/// shows the flag.
/// </remarks>
internal sealed class FinsResponse
{
    private readonly byte[] _data;

    /// <summary>Creates a response.</summary>
    public FinsResponse(int unit, FinsHeader header, ushort commandCode, FinsEndCode endCode, ReadOnlySpan<byte> data)
    {
        Unit = unit;
        Header = header;
        CommandCode = commandCode;
        EndCode = endCode;
        _data = data.ToArray();
    }

    /// <summary>The Host Link unit number that answered.</summary>
    public int Unit { get; }

    /// <summary>The response's FINS header (ICF 40 or C0, addresses as the PLC sent them).</summary>
    public FinsHeader Header { get; }

    /// <summary>The command code the response echoes.</summary>
    public ushort CommandCode { get; }

    /// <summary>The response code, flags included.</summary>
    public FinsEndCode EndCode { get; }

    /// <summary>True when the command completed (the CPU error flags may still be set).</summary>
    public bool IsSuccess => EndCode.IsSuccess;

    /// <summary>The response data after MRES SRES.</summary>
    public ReadOnlyMemory<byte> Data => _data;

    /// <summary>Throws <see cref="FinsEndCodeException"/> unless the response code, flags masked, is 0000.</summary>
    /// <exception cref="FinsEndCodeException">The PLC reported an error.</exception>
    public void ThrowIfError()
    {
        if (!EndCode.IsSuccess)
        {
            throw new FinsEndCodeException(EndCode, CommandCode, Unit);
        }
    }

    /// <summary>
    /// Parses a whole frame: validates it with <see cref="FrameParser.ParseFirst"/>, checks the unit, the <c>FA</c>
    /// header and the <c>*</c>CR ending (FA frames are never split), then parses the text with the echo checks of
    /// <see cref="Parse(ReadOnlySpan{byte}, int, FinsHeader, ushort)"/>.
    /// </summary>
    /// <exception cref="HostLinkFrameException">The frame is damaged, from another unit, not an FA frame, or does not echo the command.</exception>
    /// <exception cref="HostLinkEndCodeException">The Host Link end code is not 00.</exception>
    public static FinsResponse ParseFrame(ReadOnlySpan<byte> frame, int unit, FinsHeader commandHeader, ushort commandCode)
    {
        FrameInfo info = FrameParser.ParseFirst(frame);
        if (info.Unit != unit)
        {
            throw new HostLinkFrameException(FrameError.WrongUnit, $"Unit {info.Unit:D2} answered; unit {unit:D2} was addressed.", frame);
        }

        CheckFaFrame(frame, info);
        return Parse(info.Text(frame), unit, commandHeader, commandCode);
    }

    /// <summary>
    /// Parses the text after <c>FA</c> of a validated response frame and checks that it answers the command: ICF 40
    /// (or C0 for a network header), the same SID, the same MRC SRC.
    /// </summary>
    /// <param name="text">The characters between <c>FA</c> and the FCS.</param>
    /// <param name="unit">The unit that answered (for messages and exceptions).</param>
    /// <param name="commandHeader">The header of the command this answers.</param>
    /// <param name="commandCode">The command code this answers.</param>
    /// <exception cref="HostLinkFrameException">
    /// <see cref="FrameError.Malformed"/> for odd length, non-hex characters or a truncated header;
    /// <see cref="FrameError.WrongHeader"/> when ICF, SID or MRC SRC do not match the command.
    /// </exception>
    /// <exception cref="HostLinkEndCodeException">The Host Link end code is not 00.</exception>
    public static FinsResponse Parse(ReadOnlySpan<byte> text, int unit, FinsHeader commandHeader, ushort commandCode)
    {
        FinsResponse response = Parse(text, unit);
        byte expectedIcf = commandHeader.IsNetwork ? FinsHeader.NetworkResponseIcf : FinsHeader.DirectResponseIcf;
        if (response.Header.Icf != expectedIcf)
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The response ICF is {response.Header.Icf:X2}; a response to this command has {expectedIcf:X2}.", text);
        }

        if (response.Header.Sid != commandHeader.Sid)
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The response SID is {response.Header.Sid:X2}; the command sent {commandHeader.Sid:X2}. It answers another command.", text);
        }

        if (response.CommandCode != commandCode)
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The response is for FINS {response.CommandCode:X4}; the command was {commandCode:X4}.", text);
        }

        return response;
    }

    /// <summary>
    /// Parses the text after <c>FA</c> of a validated response frame without matching it to a command (for
    /// monitors and tests): only the response ICF bit is checked.
    /// </summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.Malformed"/>: odd length, non-hex characters, truncated header, or not a response.</exception>
    /// <exception cref="HostLinkEndCodeException">The Host Link end code is not 00.</exception>
    public static FinsResponse Parse(ReadOnlySpan<byte> text, int unit)
    {
        if (text.Length < 2 || !EndCodes.TryParse(text.Slice(0, 2), out OmronHostLink.EndCode hostLinkEnd))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FA response does not start with a two-digit Host Link end code.", text);
        }

        if (hostLinkEnd != OmronHostLink.EndCode.NormalCompletion)
        {
            throw new HostLinkEndCodeException(hostLinkEnd, CMode.CModeCommands.Fins.Header, unit);
        }

        ReadOnlySpan<byte> hex = text.Slice(2);
        var bytes = new byte[hex.Length / 2];
        if (!FinsBytes.TryParseHex(hex, bytes))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FINS part of the response is not an even number of hex characters.", text);
        }

        if (!FinsHeader.TryRead(bytes, 0, out FinsHeader header) || bytes.Length < header.Length + 4)
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FINS response is too short to hold its header, command code and response code.", text);
        }

        if (!header.IsResponse)
        {
            throw new HostLinkFrameException(FrameError.Malformed, $"ICF {header.Icf:X2} does not mark a response.", text);
        }

        int at = header.Length;
        ushort command = FinsBytes.ReadUInt16(bytes, at);
        var endCode = new FinsEndCode(FinsBytes.ReadUInt16(bytes, at + 2));
        return new FinsResponse(unit, header, command, endCode, bytes.AsSpan(at + 4));
    }

    internal static void CheckFaFrame(ReadOnlySpan<byte> frame, FrameInfo info)
    {
        ReadOnlySpan<byte> h = info.Header(frame);
        if (h[0] != (byte)'F' || h[1] != (byte)'A')
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The frame's header is '{FrameText.Printable(h)}', not FA.", frame);
        }

        if (!info.IsFinal)
        {
            throw new HostLinkFrameException(FrameError.Malformed, "An FA frame ends with a CR delimiter; FINS over Host Link frames are never split.", frame);
        }
    }
}
