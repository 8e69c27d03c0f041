using System.Globalization;

namespace OmronHostLink;

/// <summary>Meanings and categories of <see cref="EndCode"/> values.</summary>
public static class EndCodes
{
    /// <summary>Parses the two characters of an end code (or <c>IC</c>).</summary>
    internal static bool TryParse(ReadOnlySpan<byte> text, out EndCode code)
    {
        if (Protocol.CMode.CModeHeaders.Is(text, Protocol.CMode.CModeCommands.UndefinedCommand.Header))
        {
            code = EndCode.UndefinedHeader;
            return true;
        }

        bool ok = Protocol.HexAscii.TryParseByte(text, out byte value);
        code = (EndCode)value;
        return ok;
    }

    /// <summary>The code as the PLC sends it: two hex digits, or <c>IC</c>.</summary>
    public static string ToCode(this EndCode code)
        => code == EndCode.UndefinedHeader ? Protocol.CMode.CModeCommands.UndefinedCommand.Header : ((int)code).ToString("X2", CultureInfo.InvariantCulture);

    /// <summary>Whether the code is one the manuals define.</summary>
    public static bool IsDefined(EndCode code) => Describe(code) is not null;

    /// <summary>The meaning of the code, in the manuals' words.</summary>
    public static string Meaning(this EndCode code) => Describe(code) ?? $"Unknown end code {code.ToCode()}";

    /// <summary>The kind of failure the code reports.</summary>
    public static EndCodeCategory Category(this EndCode code) => code switch
    {
        EndCode.NormalCompletion => EndCodeCategory.None,
        EndCode.NotExecutableInRunMode or EndCode.NotExecutableInMonitorMode
            or EndCode.NotExecutableInProgramMode or EndCode.NotExecutableInDebugMode => EndCodeCategory.ModeNotAllowed,
        EndCode.AddressOver or EndCode.EntryNumberDataError or EndCode.AbortedEntryNumberDataError => EndCodeCategory.AddressOrEntry,
        EndCode.FcsError or EndCode.AbortedFcsError or EndCode.ParityError or EndCode.FramingError or EndCode.Overrun
            or EndCode.AbortedParityError or EndCode.AbortedFramingError or EndCode.AbortedOverrun => EndCodeCategory.FrameDamaged,
        EndCode.FormatError or EndCode.AbortedFormatError => EndCodeCategory.Format,
        EndCode.FrameLengthError or EndCode.AbortedFrameLengthError => EndCodeCategory.Length,
        EndCode.CommandNotSupported or EndCode.UndefinedHeader => EndCodeCategory.NotSupported,
        EndCode.WriteProtected or EndCode.UserMemoryProtected => EndCodeCategory.Protected,
        EndCode.CpuUnitError => EndCodeCategory.CpuError,
        _ => EndCodeCategory.NotExecutable,
    };

    /// <summary>
    /// Whether the code reports a frame the PLC received damaged (13, A3; on CV-series also 10–12 and A0–A2): the same
    /// command, sent again, may get through.
    /// </summary>
    public static bool IsTransient(this EndCode code) => code.Category() == EndCodeCategory.FrameDamaged;

    /// <summary>Every end code the manuals define.</summary>
    public static IReadOnlyList<EndCode> All { get; } =
#if NET
        Enum.GetValues<EndCode>();
#else
        (EndCode[])Enum.GetValues(typeof(EndCode));
#endif

    private static string? Describe(EndCode code) => code switch
    {
        EndCode.NormalCompletion => "Normal completion",
        EndCode.NotExecutableInRunMode => "Not executable in RUN mode",
        EndCode.NotExecutableInMonitorMode => "Not executable in MONITOR mode",
        EndCode.WriteProtected => "UM write-protected",
        EndCode.AddressOver => "Address over: the program address is beyond the end of the program",
        EndCode.NotExecutableInProgramMode => "Not executable in PROGRAM mode",
        EndCode.NotExecutableInDebugMode => "Not executable in DEBUG mode",
        EndCode.ParityError => "Parity error",
        EndCode.FramingError => "Framing error",
        EndCode.Overrun => "Overrun",
        EndCode.FcsError => "FCS error: the PLC received a frame whose check characters did not match",
        EndCode.FormatError => "Format error: wrong command length or format, or a command that may not be divided was divided",
        EndCode.EntryNumberDataError => "Entry number data error: an address or count is out of range or not in BCD/hex",
        EndCode.CommandNotSupported => "Command not supported, or the SV operand was not found",
        EndCode.FrameLengthError => "Frame length error: the frame is longer than the PLC accepts",
        EndCode.NotExecutable => "Not executable: nothing registered, SV over 9999, or no access right",
        EndCode.CouldNotCreateIoTable => "The I/O table could not be created",
        EndCode.CpuUnitError => "Not executable because of a CPU Unit error",
        EndCode.MemoryMissing => "Memory does not exist",
        EndCode.UserMemoryProtected => "User memory is protected",
        EndCode.AbortedParityError => "Aborted: parity error in transmitted data",
        EndCode.AbortedFramingError => "Aborted: framing error in transmitted data",
        EndCode.AbortedOverrun => "Aborted: overrun in transmitted data",
        EndCode.AbortedFcsError => "Aborted: FCS error in the second or a later frame",
        EndCode.AbortedFormatError => "Aborted: format error in the second or a later frame",
        EndCode.AbortedEntryNumberDataError => "Aborted: entry number data error in the second or a later frame",
        EndCode.AbortedFrameLengthError => "Aborted: frame length error in the second or a later frame",
        EndCode.ProgramAreaError => "Program area error",
        EndCode.UndefinedHeader => "The PLC does not recognise the command header (IC response)",
        _ => null,
    };
}
