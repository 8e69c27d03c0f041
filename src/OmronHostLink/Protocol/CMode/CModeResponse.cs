using System.Text;

namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// Decoding of C-mode response text (the text of every frame joined: end code, then data) and encoding of responses
/// from the PLC side. Anything that does not have the exact expected shape is a <see cref="HostLinkFrameException"/>.
/// </summary>
internal static class CModeResponse
{
    /// <summary>Characters before the end code in a first response frame: <c>@</c>, unit, header.</summary>
    public const int PrefixLength = MessagePrefix.Length;

    /// <summary>Length of the end code.</summary>
    public const int EndCodeLength = 2;

    /// <summary>
    /// Checks that a validated first answer frame answers the command: the unit it was sent to and the header it
    /// carried. An IC answer (the PLC does not know the header) carries no text and means end code
    /// <see cref="EndCode.UndefinedHeader"/>.
    /// </summary>
    /// <exception cref="HostLinkFrameException">Another unit or header answered, or an IC answer carries text.</exception>
    /// <exception cref="HostLinkEndCodeException">The PLC answered IC.</exception>
    internal static void CheckAnswerHeader(ReadOnlySpan<byte> frame, FrameInfo info, int unit, string header)
    {
        if (info.Unit != unit)
        {
            throw new HostLinkFrameException(FrameError.WrongUnit, $"Unit {info.Unit:D2} answered a command sent to unit {unit:D2}.", frame.Slice(0, Math.Min(frame.Length, 16)));
        }

        ReadOnlySpan<byte> answered = info.Header(frame);
        if (answered[0] == (byte)'I' && answered[1] == (byte)'C' && header != "IC")
        {
            if (!info.IsFinal || info.TextLength != 0)
            {
                throw new HostLinkFrameException(FrameError.Malformed, "An IC answer carries no text.");
            }

            throw new HostLinkEndCodeException(EndCode.UndefinedHeader, header, unit);
        }

        if (answered[0] != (byte)header[0] || answered[1] != (byte)header[1])
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The answer's header {FrameText.Printable(answered)} does not echo the command's {header}.");
        }
    }

    /// <summary>Reads the end code at the start of <paramref name="text"/>.</summary>
    /// <exception cref="HostLinkFrameException">There is no valid end code.</exception>
    public static EndCode ReadEndCode(ReadOnlySpan<byte> text)
    {
        if (text.Length < EndCodeLength || !HexAscii.TryParseByte(text.Slice(0, EndCodeLength), out byte code))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The response has no valid two-digit end code.", text);
        }

        return (EndCode)code;
    }

    /// <summary>Checks the end code and returns the data after it.</summary>
    /// <exception cref="HostLinkEndCodeException">The end code is not 00.</exception>
    /// <exception cref="HostLinkFrameException">There is no valid end code.</exception>
    public static ReadOnlySpan<byte> GetData(ReadOnlySpan<byte> text, string header, int unit)
    {
        EndCode code = ReadEndCode(text);
        if (code != EndCode.NormalCompletion)
        {
            throw new HostLinkEndCodeException(code, header, unit);
        }

        return text.Slice(EndCodeLength);
    }

    /// <summary>Reads exactly <paramref name="destination"/>.Length words of 4 hex digits.</summary>
    /// <exception cref="HostLinkFrameException">The data has another length or a non-hex character.</exception>
    public static void ReadWords(ReadOnlySpan<byte> data, Span<ushort> destination)
    {
        if (data.Length != destination.Length * 4)
        {
            throw WrongLength(data.Length, destination.Length * 4, $"{destination.Length} words");
        }

        if (!HexAscii.TryParseWords(data, destination))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The response data holds a character that is not a hex digit.", data);
        }
    }

    /// <summary>Reads RG completion flags: one character per point, <c>1</c> on, <c>0</c> off.</summary>
    /// <exception cref="HostLinkFrameException">The data has another length or another character.</exception>
    public static void ReadFlags(ReadOnlySpan<byte> data, Span<bool> destination)
    {
        if (data.Length != destination.Length)
        {
            throw WrongLength(data.Length, destination.Length, $"{destination.Length} flags");
        }

        for (int i = 0; i < data.Length; i++)
        {
            destination[i] = data[i] switch
            {
                (byte)'1' => true,
                (byte)'0' => false,
                _ => throw new HostLinkFrameException(FrameError.Malformed, $"Flag {i} is '{(char)data[i]}', not 0 or 1.", data),
            };
        }
    }

    /// <summary>Reads the MS answer: a status word and, when present, a 16-character FAL/FALS message.</summary>
    public static PlcStatus ReadStatus(ReadOnlySpan<byte> data)
    {
        if (data.Length != 4 && data.Length != 20)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"An MS answer holds 4 or 20 characters of data; it held {data.Length}.", data);
        }

        if (!HexAscii.TryParseWord(data.Slice(0, 4), out ushort status))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "The MS status word is not hex.", data);
        }

        PlcMode mode = ((status >> 8) & 0x3) switch
        {
            0 => PlcMode.Program,
            2 => PlcMode.Run,
            3 => PlcMode.Monitor,
            _ => throw new HostLinkFrameException(FrameError.Malformed, $"MS status {status:X4} names no operating mode (bits 9-8 = 01).", data),
        };

        // Some units send the 16 message characters as spaces when no FAL/FALS has run (a Serial Communications Unit
        // in Host Link-compatible mode B, W336 p301); that is no message, as when they are left out.
        string? message = data.Length == 20 ? Encoding.ASCII.GetString(data.Slice(4, 16).ToArray()).TrimEnd() : null;
        return new PlcStatus(mode, status, string.IsNullOrEmpty(message) ? null : message);
    }

    /// <summary>The MS status word for a mode (bits 9-8), as a PLC writes it.</summary>
    public static ushort StatusWord(PlcMode mode, byte lowByte = 0) => (ushort)((mode switch
    {
        PlcMode.Program => 0x0000,
        PlcMode.Run => 0x0200,
        _ => 0x0300,
    }) | lowByte);

    /// <summary>Reads the MF answer: two words of error information.</summary>
    public static PlcErrorInfo ReadErrors(ReadOnlySpan<byte> data)
    {
        Span<ushort> words = stackalloc ushort[2];
        ReadWords(data, words);
        return new PlcErrorInfo(words[0], words[1]);
    }

    /// <summary>Reads the MM answer: a two-digit model code.</summary>
    public static PlcModel ReadModel(ReadOnlySpan<byte> data)
    {
        if (data.Length != 2 || !HexAscii.TryParseByte(data, out byte code))
        {
            throw new HostLinkFrameException(FrameError.Malformed, "An MM answer holds a two-digit model code.", data);
        }

        return new PlcModel(code);
    }

    /// <summary>
    /// Checks a TS answer. TS success carries no end code: the text must come back exactly as sent. An answer of two
    /// characters that differs from the text is an end code (13, 14, 18, 21).
    /// </summary>
    /// <exception cref="HostLinkEndCodeException">The PLC answered an end code.</exception>
    /// <exception cref="HostLinkFrameException">The echo differs from the text sent.</exception>
    public static void CheckTestEcho(ReadOnlySpan<byte> text, ReadOnlySpan<byte> sent, int unit)
    {
        if (text.SequenceEqual(sent))
        {
            return;
        }

        if (text.Length == EndCodeLength && HexAscii.TryParseByte(text, out byte code) && code != 0)
        {
            throw new HostLinkEndCodeException((EndCode)code, CModeCommands.Test.Header, unit);
        }

        throw new HostLinkFrameException(FrameError.Malformed, $"The TS echo '{FrameText.Printable(text)}' differs from the text sent '{FrameText.Printable(sent)}'.");
    }

    /// <summary>Writes the unframed response message <c>@</c> + unit + header + end code + data (PLC side).</summary>
    /// <returns>The number of characters written.</returns>
    public static int WriteMessage(Span<byte> destination, int unit, string header, EndCode code, ReadOnlySpan<byte> data)
    {
        MessagePrefix.Write(destination, unit, header);
        HexAscii.WriteByte((byte)code, destination.Slice(PrefixLength, EndCodeLength));
        data.CopyTo(destination.Slice(PrefixLength + EndCodeLength));
        return PrefixLength + EndCodeLength + data.Length;
    }

    /// <summary>Writes a response message with no end code (TS echo, IC), PLC side.</summary>
    /// <returns>The number of characters written.</returns>
    public static int WriteMessageWithoutEndCode(Span<byte> destination, int unit, string header, ReadOnlySpan<byte> text)
    {
        MessagePrefix.Write(destination, unit, header);
        text.CopyTo(destination.Slice(PrefixLength));
        return PrefixLength + text.Length;
    }

    private static HostLinkFrameException WrongLength(int found, int expected, string what)
        => new(FrameError.WrongLength, $"The response should carry {expected} data characters ({what}) but carried {found}.");
}
