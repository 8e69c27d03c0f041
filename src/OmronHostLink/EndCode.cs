namespace OmronHostLink;

/// <summary>
/// C-mode end codes (W342 §4-1-3; C200HX; CQM1H). The numeric value is the code as printed in the manuals, read as hex:
/// end code <c>13</c> (FCS error) is <c>0x13</c>. <see cref="UndefinedHeader"/> stands for the IC response, which
/// carries no end code.
/// </summary>
public enum EndCode
{
    /// <summary>00: normal completion.</summary>
    NormalCompletion = 0x00,

    /// <summary>01: not executable in RUN mode.</summary>
    NotExecutableInRunMode = 0x01,

    /// <summary>02: not executable in MONITOR mode.</summary>
    NotExecutableInMonitorMode = 0x02,

    /// <summary>03: UM write-protected (older models: PROM mounted).</summary>
    WriteProtected = 0x03,

    /// <summary>04: address over (program address beyond the end).</summary>
    AddressOver = 0x04,

    /// <summary>0B: not executable in PROGRAM mode.</summary>
    NotExecutableInProgramMode = 0x0B,

    /// <summary>0C: not executable in DEBUG mode (CV/C-alpha series only).</summary>
    NotExecutableInDebugMode = 0x0C,

    /// <summary>10: parity error (CV/C-alpha series only).</summary>
    ParityError = 0x10,

    /// <summary>11: framing error (CV/C-alpha series only).</summary>
    FramingError = 0x11,

    /// <summary>12: overrun (CV/C-alpha series only).</summary>
    Overrun = 0x12,

    /// <summary>13: FCS error.</summary>
    FcsError = 0x13,

    /// <summary>14: format error (wrong length, a command that may not be divided was divided, too short).</summary>
    FormatError = 0x14,

    /// <summary>15: entry number data error (out of range, not BCD or hex, count 0).</summary>
    EntryNumberDataError = 0x15,

    /// <summary>16: command not supported (for SV commands: the operand was not found).</summary>
    CommandNotSupported = 0x16,

    /// <summary>18: frame length error (the frame is longer than the unit accepts).</summary>
    FrameLengthError = 0x18,

    /// <summary>19: not executable (nothing registered, SV over 9999, no access right).</summary>
    NotExecutable = 0x19,

    /// <summary>20: the I/O table could not be created.</summary>
    CouldNotCreateIoTable = 0x20,

    /// <summary>21: not executable because of a CPU Unit error.</summary>
    CpuUnitError = 0x21,

    /// <summary>22: memory does not exist (CV/C-alpha series only).</summary>
    MemoryMissing = 0x22,

    /// <summary>23: user memory protected (read/write protection).</summary>
    UserMemoryProtected = 0x23,

    /// <summary>A0: aborted because of a parity error in transmitted data (CV/C-alpha series only).</summary>
    AbortedParityError = 0xA0,

    /// <summary>A1: aborted because of a framing error in transmitted data (CV/C-alpha series only).</summary>
    AbortedFramingError = 0xA1,

    /// <summary>A2: aborted because of an overrun in transmitted data (CV/C-alpha series only).</summary>
    AbortedOverrun = 0xA2,

    /// <summary>A3: aborted because of an FCS error in the second or a later frame.</summary>
    AbortedFcsError = 0xA3,

    /// <summary>A4: aborted because of a format error in the second or a later frame.</summary>
    AbortedFormatError = 0xA4,

    /// <summary>A5: aborted because of an entry number data error in the second or a later frame.</summary>
    AbortedEntryNumberDataError = 0xA5,

    /// <summary>A8: aborted because of a frame length error in the second or a later frame.</summary>
    AbortedFrameLengthError = 0xA8,

    /// <summary>B0: program area error (CV/C-alpha series only).</summary>
    ProgramAreaError = 0xB0,

    /// <summary>IC: the PLC did not recognise the command header (the IC response has no end code).</summary>
    UndefinedHeader = 0x1C0,
}
