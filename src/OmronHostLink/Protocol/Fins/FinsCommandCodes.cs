namespace OmronHostLink.Protocol.Fins;

/// <summary>FINS command codes (MRC × 256 + SRC) this library models.</summary>
internal static class FinsCommandCodes
{
    /// <summary>0101 MEMORY AREA READ.</summary>
    public const ushort MemoryAreaRead = 0x0101;

    /// <summary>0102 MEMORY AREA WRITE.</summary>
    public const ushort MemoryAreaWrite = 0x0102;

    /// <summary>0103 MEMORY AREA FILL.</summary>
    public const ushort MemoryAreaFill = 0x0103;

    /// <summary>0104 MULTIPLE MEMORY AREA READ.</summary>
    public const ushort MultipleMemoryAreaRead = 0x0104;

    /// <summary>0105 MEMORY AREA TRANSFER.</summary>
    public const ushort MemoryAreaTransfer = 0x0105;

    /// <summary>0401 RUN.</summary>
    public const ushort Run = 0x0401;

    /// <summary>0402 STOP.</summary>
    public const ushort Stop = 0x0402;

    /// <summary>0501 CPU UNIT DATA READ.</summary>
    public const ushort CpuUnitDataRead = 0x0501;

    /// <summary>0601 CPU UNIT STATUS READ.</summary>
    public const ushort CpuUnitStatusRead = 0x0601;

    /// <summary>0620 CYCLE TIME READ.</summary>
    public const ushort CycleTimeRead = 0x0620;

    /// <summary>0701 CLOCK READ.</summary>
    public const ushort ClockRead = 0x0701;

    /// <summary>0702 CLOCK WRITE.</summary>
    public const ushort ClockWrite = 0x0702;

    /// <summary>2101 ERROR CLEAR.</summary>
    public const ushort ErrorClear = 0x2101;

    /// <summary>2102 ERROR LOG READ.</summary>
    public const ushort ErrorLogRead = 0x2102;

    /// <summary>2301 FORCED SET/RESET.</summary>
    public const ushort ForcedSetReset = 0x2301;

    /// <summary>2302 FORCED SET/RESET CANCEL.</summary>
    public const ushort ForcedSetResetCancel = 0x2302;

    /// <summary>The manuals' name of a command code, or null for a code this library does not model.</summary>
    public static string? Name(ushort code) => code switch
    {
        MemoryAreaRead => "MEMORY AREA READ",
        MemoryAreaWrite => "MEMORY AREA WRITE",
        MemoryAreaFill => "MEMORY AREA FILL",
        MultipleMemoryAreaRead => "MULTIPLE MEMORY AREA READ",
        MemoryAreaTransfer => "MEMORY AREA TRANSFER",
        Run => "RUN",
        Stop => "STOP",
        CpuUnitDataRead => "CPU UNIT DATA READ",
        CpuUnitStatusRead => "CPU UNIT STATUS READ",
        CycleTimeRead => "CYCLE TIME READ",
        ClockRead => "CLOCK READ",
        ClockWrite => "CLOCK WRITE",
        ErrorClear => "ERROR CLEAR",
        ErrorLogRead => "ERROR LOG READ",
        ForcedSetReset => "FORCED SET/RESET",
        ForcedSetResetCancel => "FORCED SET/RESET CANCEL",
        _ => null,
    };

    /// <summary>The manuals' name of a command code, or its hex digits for one this library does not model.</summary>
    public static string Describe(ushort code) => Name(code) ?? $"command {code:X4}";
}
