namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// Writes and reads the unframed text of FINS-over-Host-Link messages (<c>@</c> + unit + <c>FA</c> + ...; the caller
/// adds FCS, <c>*</c> and CR with <see cref="FrameWriter.WriteFrame(ReadOnlySpan{byte}, bool, Span{byte})"/>, or uses the
/// <c>Encode…Frame</c> helpers). FA frames are never split into 131-character frames.
/// </summary>
/// <remarks>
/// <para>Command: <c>@</c> unit(2) <c>FA</c> wait(1 hex char) then hex bytes: FINS header, MRC SRC, parameters.</para>
/// <para>Response: <c>@</c> unit(2) <c>FA</c> Host Link end code(2) then hex bytes: FINS header, MRC SRC, MRES SRES, data.</para>
/// </remarks>
internal static class FinsMessage
{
    /// <summary>The longest FA frame, FCS and <c>*</c>CR included (W342 p69, stated for responses; applied to commands too).</summary>
    public const int MaxFrameLength = 1115;

    /// <summary>The most response data bytes after MRES SRES (1,076 characters, W342 p69).</summary>
    public const int MaxResponseDataLength = MemoryAreaReadCommand.MaxResponseDataBytes;

    /// <summary>Length of a Host Link-level error response, unframed: <c>@</c> unit <c>FA</c> end code.</summary>
    public const int HostLinkErrorLength = 7;

    /// <summary>Characters of <c>@</c> + unit + <c>FA</c>.</summary>
    private const int Prefix = MessagePrefix.Length;

    /// <summary>
    /// The most answer text an FA exchange holds: the Host Link end code, then the header, the command code, the end
    /// code and <paramref name="maxResponseData"/> data bytes, two characters a byte.
    /// </summary>
    internal static int GetMaxAnswerTextLength(FinsHeader header, int maxResponseData)
        => ResponseLength(header.Length, maxResponseData) - Prefix;

    /// <summary>How an FA command of <paramref name="messageLength"/> characters travels and is answered.</summary>
    internal static ExchangeShape GetExchange(int messageLength, FinsHeader header, int maxResponseData)
        => ExchangeShape.Fins(messageLength, GetMaxAnswerTextLength(header, maxResponseData));

    /// <summary>Characters of the unframed command message for <paramref name="header"/> and <paramref name="command"/>.</summary>
    public static int GetCommandLength(FinsHeader header, FinsCommand command)
        => CommandLength(header.Length, Guard.NotNull(command).ParameterLength);

    /// <summary>Characters of the unframed response message to a command with <paramref name="commandHeader"/>, carrying <paramref name="dataLength"/> data bytes.</summary>
    public static int GetResponseLength(FinsHeader commandHeader, int dataLength)
        => ResponseLength(commandHeader.Length, dataLength);

    /// <summary>Characters of a command frame to the CPU Unit (direct header) carrying <paramref name="parameterLength"/> parameter bytes, FCS and <c>*</c>CR included.</summary>
    public static int DirectCommandFrameLength(int parameterLength)
        => CommandLength(FinsHeader.DirectLength, parameterLength) + FrameWriter.FinalOverhead;

    /// <summary>Characters of the answer frame to a direct command carrying <paramref name="dataLength"/> data bytes, FCS and <c>*</c>CR included.</summary>
    public static int DirectResponseFrameLength(int dataLength)
        => ResponseLength(FinsHeader.DirectLength, dataLength) + FrameWriter.FinalOverhead;

    // @ unit FA, the wait character, then header, MRC SRC and parameters in hex.
    private static int CommandLength(int headerLength, int parameterLength) => Prefix + 1 + (2 * (headerLength + 2 + parameterLength));

    // @ unit FA, the Host Link end code, then header, MRC SRC, MRES SRES and data in hex.
    private static int ResponseLength(int headerLength, int dataLength) => Prefix + 2 + (2 * (headerLength + 4 + dataLength));

    /// <summary>
    /// Writes the unframed command: <c>@</c> unit <c>FA</c> wait, then header, MRC SRC and parameters in hex.
    /// </summary>
    /// <returns>The number of characters written (<see cref="GetCommandLength"/>).</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is outside 0–31.</exception>
    /// <exception cref="ArgumentException">The header is a response header, the framed command would exceed <see cref="MaxFrameLength"/>, or the destination is too small.</exception>
    public static int WriteCommand(Span<byte> destination, int unit, FinsHeader header, FinsCommand command)
    {
        Guard.Unit(unit);
        Guard.NotNull(command);
        if (header.IsResponse)
        {
            throw new ArgumentException($"ICF {header.Icf:X2} marks a response; a command needs a command header.", nameof(header));
        }

        int length = GetCommandLength(header, command);
        if (length + FrameWriter.FinalOverhead > MaxFrameLength)
        {
            throw new ArgumentException($"FINS {command.CommandCode:X4} would take a {length + FrameWriter.FinalOverhead}-character frame; an FA frame holds at most {MaxFrameLength}.", nameof(command));
        }

        if (destination.Length < length)
        {
            throw new ArgumentException($"The destination holds {destination.Length} characters; the command needs {length}.", nameof(destination));
        }

        WritePrefix(destination, unit);
        destination[Prefix] = HexAscii.Nibble(header.ResponseWait);

        // Raw bytes go in the second half of the hex region, then expand in place into hex.
        int count = header.Length + 2 + command.ParameterLength;
        Span<byte> text = destination.Slice(Prefix + 1, count * 2);
        Span<byte> raw = text.Slice(count);
        int at = header.Write(raw);
        FinsBytes.WriteUInt16(raw, at, command.CommandCode);
        command.WriteParameters(raw.Slice(at + 2, command.ParameterLength));
        FinsBytes.ExpandHexInPlace(text, count);
        return length;
    }

    /// <summary>The whole command frame (with FCS and <c>*</c>CR) as a new array.</summary>
    /// <exception cref="ArgumentException">See <see cref="WriteCommand"/>.</exception>
    public static byte[] EncodeCommandFrame(int unit, FinsHeader header, FinsCommand command)
    {
        var frame = new byte[GetCommandLength(header, command) + FrameWriter.FinalOverhead];
        int length = WriteCommand(frame, unit, header, command);
        FrameWriter.WriteFrame(frame.AsSpan(0, length), final: true, frame);
        return frame;
    }

    /// <summary>
    /// Parses the text after <c>FA</c> of a validated command frame: the wait character, then the hex FINS header,
    /// MRC SRC and parameters. The parameters are not interpreted (see <see cref="FinsCommandMessage.ToCommand"/>).
    /// </summary>
    /// <param name="text">The characters between <c>FA</c> and the FCS.</param>
    /// <param name="unit">The unit the frame was addressed to.</param>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.Malformed"/>: no wait character, odd length, non-hex characters, truncated header, or a response ICF.</exception>
    public static FinsCommandMessage ParseCommand(ReadOnlySpan<byte> text, int unit)
    {
        if (text.IsEmpty || !HexAscii.TryParseNibble(text[0], out int wait))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FA command does not start with a hex response wait character.", text);
        }

        ReadOnlySpan<byte> hex = text.Slice(1);
        var bytes = new byte[hex.Length / 2];
        if (!FinsBytes.TryParseHex(hex, bytes))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FINS part of the command is not an even number of hex characters.", text);
        }

        if (!FinsHeader.TryRead(bytes, wait, out FinsHeader header) || bytes.Length < header.Length + 2)
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The FINS command is too short to hold its header and command code.", text);
        }

        if (header.IsResponse)
        {
            throw new HostLinkFrameException(FrameError.Malformed, $"ICF {header.Icf:X2} marks a response, not a command.", text);
        }

        ushort code = FinsBytes.ReadUInt16(bytes, header.Length);
        return new FinsCommandMessage(unit, header, code, bytes.AsSpan(header.Length + 2));
    }

    /// <summary>
    /// Validates a whole command frame (FCS, <c>FA</c> header, <c>*</c>CR ending) and parses it with
    /// <see cref="ParseCommand"/>.
    /// </summary>
    /// <exception cref="HostLinkFrameException">The frame is damaged, not an FA frame, or malformed.</exception>
    public static FinsCommandMessage ParseCommandFrame(ReadOnlySpan<byte> frame)
    {
        FrameInfo info = FrameParser.ParseFirst(frame);
        FinsResponse.CheckFaFrame(frame, info);
        return ParseCommand(info.Text(frame), info.Unit);
    }

    /// <summary>
    /// Writes the unframed response to a command: <c>@</c> unit <c>FA00</c>, then the response header (ICF 40 or C0,
    /// SID echoed, source and destination swapped; see <see cref="FinsHeader.ToResponseHeader"/>), MRC SRC,
    /// MRES SRES and data in hex.
    /// </summary>
    /// <returns>The number of characters written (<see cref="GetResponseLength"/>).</returns>
    /// <exception cref="ArgumentOutOfRangeException">The unit is outside 0–31.</exception>
    /// <exception cref="ArgumentException">More than <see cref="MaxResponseDataLength"/> data bytes, or the destination is too small.</exception>
    public static int WriteResponse(Span<byte> destination, int unit, FinsHeader commandHeader, ushort commandCode, FinsEndCode code, ReadOnlySpan<byte> data)
    {
        Guard.Unit(unit);
        if (data.Length > MaxResponseDataLength)
        {
            throw new ArgumentException($"An FA response carries at most {MaxResponseDataLength} data bytes; {data.Length} were given (answer 110B with the data that fits).", nameof(data));
        }

        int length = GetResponseLength(commandHeader, data.Length);
        if (destination.Length < length)
        {
            throw new ArgumentException($"The destination holds {destination.Length} characters; the response needs {length}.", nameof(destination));
        }

        WritePrefix(destination, unit);
        destination[Prefix] = (byte)'0';
        destination[Prefix + 1] = (byte)'0';

        FinsHeader header = commandHeader.ToResponseHeader();
        int count = header.Length + 4 + data.Length;
        Span<byte> text = destination.Slice(Prefix + 2, count * 2);
        Span<byte> raw = text.Slice(count);
        int at = header.Write(raw);
        FinsBytes.WriteUInt16(raw, at, commandCode);
        FinsBytes.WriteUInt16(raw, at + 2, code.Raw);
        data.CopyTo(raw.Slice(at + 4));
        FinsBytes.ExpandHexInPlace(text, count);
        return length;
    }

    /// <summary>The whole response frame (with FCS and <c>*</c>CR) as a new array.</summary>
    /// <exception cref="ArgumentException">See <see cref="WriteResponse"/>.</exception>
    public static byte[] EncodeResponseFrame(int unit, FinsHeader commandHeader, ushort commandCode, FinsEndCode code, ReadOnlySpan<byte> data)
    {
        var frame = new byte[GetResponseLength(commandHeader, data.Length) + FrameWriter.FinalOverhead];
        int length = WriteResponse(frame, unit, commandHeader, commandCode, code, data);
        FrameWriter.WriteFrame(frame.AsSpan(0, length), final: true, frame);
        return frame;
    }

    /// <summary>
    /// Writes the unframed Host Link-level rejection of an FA frame: <c>@</c> unit <c>FA</c> end code, with no FINS
    /// part (for example <c>@00FA14</c> for a format error).
    /// </summary>
    /// <returns><see cref="HostLinkErrorLength"/>.</returns>
    /// <exception cref="ArgumentException">The end code is 00 or IC, which are not Host Link rejections, or the destination is too small.</exception>
    public static int WriteHostLinkError(Span<byte> destination, int unit, EndCode endCode)
    {
        Guard.Unit(unit);
        if (endCode is EndCode.NormalCompletion or EndCode.UndefinedHeader)
        {
            throw new ArgumentException($"End code {endCode.ToCode()} is not a Host Link rejection of an FA frame.", nameof(endCode));
        }

        if (destination.Length < HostLinkErrorLength)
        {
            throw new ArgumentException("The destination is too small.", nameof(destination));
        }

        WritePrefix(destination, unit);
        HexAscii.WriteByte((byte)endCode, destination.Slice(Prefix, 2));
        return HostLinkErrorLength;
    }

    /// <summary>The whole Host Link-level error frame (with FCS and <c>*</c>CR) as a new array.</summary>
    public static byte[] EncodeHostLinkErrorFrame(int unit, EndCode endCode)
    {
        var frame = new byte[HostLinkErrorLength + FrameWriter.FinalOverhead];
        int length = WriteHostLinkError(frame, unit, endCode);
        FrameWriter.WriteFrame(frame.AsSpan(0, length), final: true, frame);
        return frame;
    }

    private static void WritePrefix(Span<byte> destination, int unit) => MessagePrefix.Write(destination, unit, CMode.CModeCommands.Fins.Header);
}
