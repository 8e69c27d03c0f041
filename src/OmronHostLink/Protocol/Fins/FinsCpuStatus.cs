namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The response data of 0601 CPU UNIT STATUS READ: status(1) mode(1) fatal error data(2) non-fatal error data(2)
/// message-exists bits(2) FAL/FALS number(2) error message(16 ASCII characters).
/// </summary>
/// <remarks>Mode codes: 00 PROGRAM, 02 MONITOR, 04 RUN (the same codes as 0401 RUN).</remarks>
public sealed class FinsCpuStatus
{
    /// <summary>Bytes of the full response data.</summary>
    internal const int Length = 26;

    /// <summary>Bytes of the response data without the error message (accepted when decoding).</summary>
    internal const int LengthWithoutMessage = 10;

    /// <summary>Characters of the error message field.</summary>
    internal const int MessageLength = 16;

    /// <summary>Creates the status.</summary>
    /// <param name="status">The status byte (bit 0: program running).</param>
    /// <param name="mode">The operating mode.</param>
    /// <param name="fatalErrors">Fatal error data bits.</param>
    /// <param name="nonFatalErrors">Non-fatal error data bits.</param>
    /// <param name="messages">Bits 0–7: MSG instruction messages 0–7 exist.</param>
    /// <param name="falNumber">The FAL/FALS number of the current error (0 = none).</param>
    /// <param name="errorMessage">The error message, at most 16 printable ASCII characters.</param>
    /// <exception cref="ArgumentException">The message is too long or not printable ASCII.</exception>
    public FinsCpuStatus(byte status, FinsCpuMode mode, ushort fatalErrors, ushort nonFatalErrors, ushort messages, ushort falNumber, string errorMessage = "")
    {
        FinsBytes.WriteAsciiPadded(Guard.NotNull(errorMessage), new byte[MessageLength]);
        Status = status;
        Mode = mode;
        FatalErrors = fatalErrors;
        NonFatalErrors = nonFatalErrors;
        Messages = messages;
        FalNumber = falNumber;
        ErrorMessage = errorMessage.TrimEnd(' ');
    }

    /// <summary>The status byte as received.</summary>
    public byte Status { get; }

    /// <summary>Bit 0 of the status: the program is running.</summary>
    public bool IsRunning => (Status & 0x01) != 0;

    /// <summary>The operating mode (00 PROGRAM, 02 MONITOR, 04 RUN; another value is kept as it is).</summary>
    public FinsCpuMode Mode { get; }

    /// <summary>Fatal error data: one bit per fatal error kind; 0 when there is none.</summary>
    public ushort FatalErrors { get; }

    /// <summary>Non-fatal error data: one bit per non-fatal error kind; 0 when there is none.</summary>
    public ushort NonFatalErrors { get; }

    /// <summary>Message-exists bits.</summary>
    public ushort Messages { get; }

    /// <summary>The FAL/FALS number of the current error, 0 when there is none.</summary>
    public ushort FalNumber { get; }

    /// <summary>The error message, trailing spaces removed (empty when there is none).</summary>
    public string ErrorMessage { get; }

    /// <summary>Decodes the response data (26 bytes, or 10 without the message).</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: another length.</exception>
    internal static FinsCpuStatus Read(ReadOnlySpan<byte> data)
    {
        if (data.Length != Length && data.Length != LengthWithoutMessage)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"CPU UNIT STATUS READ data holds {data.Length} bytes; it should hold {Length}.");
        }

        return new FinsCpuStatus(
            data[0],
            (FinsCpuMode)data[1],
            FinsBytes.ReadUInt16(data, 2),
            FinsBytes.ReadUInt16(data, 4),
            FinsBytes.ReadUInt16(data, 6),
            FinsBytes.ReadUInt16(data, 8),
            data.Length == Length ? FinsBytes.AsciiTrimmed(data.Slice(LengthWithoutMessage, MessageLength)) : string.Empty);
    }

    /// <summary>Encodes the 26 bytes of response data (the message padded with spaces).</summary>
    /// <returns><see cref="Length"/>.</returns>
    internal int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the CPU status.", nameof(destination));
        }

        destination[0] = Status;
        destination[1] = (byte)Mode;
        FinsBytes.WriteUInt16(destination, 2, FatalErrors);
        FinsBytes.WriteUInt16(destination, 4, NonFatalErrors);
        FinsBytes.WriteUInt16(destination, 6, Messages);
        FinsBytes.WriteUInt16(destination, 8, FalNumber);
        FinsBytes.WriteAsciiPadded(ErrorMessage, destination.Slice(LengthWithoutMessage, MessageLength));
        return Length;
    }

    /// <summary>The FINS mode of a <see cref="PlcMode"/> (a PLC in any other state reports RUN).</summary>
    internal static FinsCpuMode ModeOf(PlcMode mode) => mode switch
    {
        PlcMode.Program => FinsCpuMode.Program,
        PlcMode.Monitor => FinsCpuMode.Monitor,
        _ => FinsCpuMode.Run,
    };

    /// <summary>A mode as the console shows it: <c>PROGRAM</c>, or <c>unknown mode 07</c>.</summary>
    internal static string ModeName(FinsCpuMode mode)
        => Enum.IsDefined(typeof(FinsCpuMode), mode) ? mode.ToString().ToUpperInvariant() : $"unknown mode {(byte)mode:X2}";
}
