using System.Globalization;

namespace OmronHostLink.Protocol.Fins;

/// <summary>Meanings of FINS response codes (W342 section 5-1-3).</summary>
public static class FinsEndCodes
{
    /// <summary>0000: normal completion.</summary>
    public const ushort NormalCompletion = 0x0000;

    /// <summary>0102: token timeout (the network is busy).</summary>
    public const ushort TokenTimeout = 0x0102;

    /// <summary>0103: retries failed (the network is busy or noisy).</summary>
    public const ushort RetriesFailed = 0x0103;

    /// <summary>0104: too many send frames.</summary>
    public const ushort TooManySendFrames = 0x0104;

    /// <summary>0204: destination node busy.</summary>
    public const ushort DestinationNodeBusy = 0x0204;

    /// <summary>0205: response timeout.</summary>
    public const ushort ResponseTimeout = 0x0205;

    /// <summary>0401: undefined command.</summary>
    public const ushort UndefinedCommand = 0x0401;

    /// <summary>0402: not supported by the model or version.</summary>
    public const ushort NotSupportedByModel = 0x0402;

    /// <summary>1001: command too long.</summary>
    public const ushort CommandTooLong = 0x1001;

    /// <summary>1002: command too short.</summary>
    public const ushort CommandTooShort = 0x1002;

    /// <summary>1003: the number of elements and the data do not match.</summary>
    public const ushort ElementsDataMismatch = 0x1003;

    /// <summary>1004: command format error.</summary>
    public const ushort CommandFormatError = 0x1004;

    /// <summary>1101: area classification missing (the area code is not one the PLC has).</summary>
    public const ushort AreaClassificationMissing = 0x1101;

    /// <summary>1102: access size error.</summary>
    public const ushort AccessSizeError = 0x1102;

    /// <summary>1103: address range error.</summary>
    public const ushort AddressRangeError = 0x1103;

    /// <summary>1104: address range exceeded.</summary>
    public const ushort AddressRangeExceeded = 0x1104;

    /// <summary>110B: response too long.</summary>
    public const ushort ResponseTooLong = 0x110B;

    /// <summary>110C: parameter error.</summary>
    public const ushort ParameterError = 0x110C;

    /// <summary>2101: write not possible, the area is read-only.</summary>
    public const ushort WriteNotPossibleReadOnly = 0x2101;

    /// <summary>2206: not executable in the current mode, the PLC is in RUN mode.</summary>
    public const ushort NotExecutableInRunMode = 0x2206;

    /// <summary>2605: the service is already executing.</summary>
    public const ushort ServiceAlreadyExecuting = 0x2605;

    /// <summary>The meaning of a response code (flags already masked off).</summary>
    public static string Describe(ushort code) => code switch
    {
        NormalCompletion => "Normal completion",
        0x0001 => "Service canceled",
        0x0101 => "Local node not in network",
        TokenTimeout => "Token timeout",
        RetriesFailed => "Retries failed",
        TooManySendFrames => "Too many send frames",
        0x0105 => "Node address range error",
        0x0106 => "Node address duplication",
        0x0201 => "Destination node not in network",
        0x0202 => "Unit missing",
        0x0203 => "Third node missing",
        DestinationNodeBusy => "Destination node busy",
        ResponseTimeout => "Response timeout",
        0x0301 => "Communications controller error",
        0x0302 => "CPU Unit error",
        0x0303 => "Controller error",
        0x0304 => "Unit number error",
        UndefinedCommand => "Undefined command",
        NotSupportedByModel => "Not supported by model/version",
        0x0501 => "Destination address setting error",
        0x0502 => "No routing tables",
        0x0503 => "Routing table error",
        0x0504 => "Too many relays",
        CommandTooLong => "Command too long",
        CommandTooShort => "Command too short",
        ElementsDataMismatch => "Elements/data don't match",
        CommandFormatError => "Command format error",
        0x1005 => "Header error",
        AreaClassificationMissing => "Area classification missing",
        AccessSizeError => "Access size error",
        AddressRangeError => "Address range error",
        AddressRangeExceeded => "Address range exceeded",
        0x1106 => "Program missing",
        0x1109 => "Relational error",
        0x110A => "Duplicate data access",
        ResponseTooLong => "Response too long",
        ParameterError => "Parameter error",
        0x2002 => "Read not possible: protected",
        0x2003 => "Read not possible: table missing",
        0x2004 => "Read not possible: data missing",
        0x2005 => "Read not possible: program missing",
        0x2006 => "Read not possible: file missing",
        0x2007 => "Read not possible: data mismatch",
        WriteNotPossibleReadOnly => "Write not possible: read-only",
        0x2102 => "Write not possible: protected (cannot write data link table)",
        0x2103 => "Write not possible: cannot register",
        0x2105 => "Write not possible: program missing",
        0x2106 => "Write not possible: file missing",
        0x2107 => "Write not possible: file name already exists",
        0x2108 => "Write not possible: cannot change",
        0x2201 => "Not executable in current mode: not possible during execution",
        0x2202 => "Not executable in current mode: not possible while running",
        0x2203 => "Not executable in current mode: wrong PLC mode (PROGRAM)",
        0x2204 => "Not executable in current mode: wrong PLC mode (DEBUG)",
        0x2205 => "Not executable in current mode: wrong PLC mode (MONITOR)",
        NotExecutableInRunMode => "Not executable in current mode: wrong PLC mode (RUN)",
        0x2207 => "Not executable in current mode: specified node not polling node",
        0x2208 => "Not executable in current mode: step cannot be executed",
        0x2301 => "No such device: file device missing",
        0x2302 => "No such device: memory missing",
        0x2303 => "No such device: clock missing",
        0x2401 => "Cannot start/stop: table missing",
        0x2502 => "Unit error: memory error",
        0x2503 => "Unit error: I/O setting error",
        0x2504 => "Unit error: too many I/O points",
        0x2505 => "Unit error: CPU bus error",
        0x2506 => "Unit error: I/O duplication",
        0x2507 => "Unit error: I/O bus error",
        0x2509 => "Unit error: SYSMAC BUS/2 error",
        0x250A => "Unit error: CPU Bus Unit error",
        0x250D => "Unit error: SYSMAC BUS number duplication",
        0x250F => "Unit error: memory error",
        0x2510 => "Unit error: SYSMAC BUS terminator missing",
        0x2601 => "Command error: no protection",
        0x2602 => "Command error: incorrect password",
        0x2604 => "Command error: protected",
        ServiceAlreadyExecuting => "Command error: service already executing",
        0x2606 => "Command error: service stopped",
        0x2607 => "Command error: no execution right",
        0x2608 => "Command error: settings not complete",
        0x2609 => "Command error: necessary items not set",
        0x260A => "Command error: number already defined",
        0x260B => "Command error: error will not clear",
        0x3001 => "Access right error: no access right",
        0x4001 => "Abort: service aborted",
        _ => "Unknown FINS response code " + code.ToString("X4", CultureInfo.InvariantCulture),
    };

    /// <summary>
    /// Whether a response code (flags masked off) reports a busy or timed-out network that may clear: 0102 token
    /// timeout, 0103 retries failed, 0104 too many send frames, 0204 destination node busy, 0205 response timeout.
    /// </summary>
    public static bool IsTransient(ushort code)
        => code is TokenTimeout or RetriesFailed or TooManySendFrames or DestinationNodeBusy or ResponseTimeout;

    /// <summary>Whether the code is one the manuals define.</summary>
    public static bool IsDefined(ushort code) => !Describe(code).StartsWith("Unknown", StringComparison.Ordinal);
}
