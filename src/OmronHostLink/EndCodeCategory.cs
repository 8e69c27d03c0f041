namespace OmronHostLink;

/// <summary>What kind of failure an end code reports, for callers that branch on the kind rather than the code.</summary>
public enum EndCodeCategory
{
    /// <summary>00: no failure.</summary>
    None,

    /// <summary>The command is not allowed in the PLC's current operating mode (01, 02, 0B, 0C).</summary>
    ModeNotAllowed,

    /// <summary>An address or entry number is out of range or not valid (04, 15, A5).</summary>
    AddressOrEntry,

    /// <summary>The PLC received a damaged frame (13, A3; also 10-12 and A0-A2 on CV-series).</summary>
    FrameDamaged,

    /// <summary>The command's format is wrong (14, A4).</summary>
    Format,

    /// <summary>A frame was too long (18, A8).</summary>
    Length,

    /// <summary>The command is not supported (16, IC).</summary>
    NotSupported,

    /// <summary>Memory is protected (03, 23).</summary>
    Protected,

    /// <summary>The CPU Unit has an error (21).</summary>
    CpuError,

    /// <summary>The command cannot be executed for another reason (19, 20, 22, B0, unknown codes).</summary>
    NotExecutable,
}
