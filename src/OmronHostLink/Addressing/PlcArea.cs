namespace OmronHostLink;

/// <summary>A memory area of a CS/CJ-series PLC, as named in CX-Programmer.</summary>
public enum PlcArea
{
    /// <summary>Core I/O area (CIO0–CIO6143); a plain number such as <c>100</c> means this area.</summary>
    Cio,

    /// <summary>Work area (W0–W511). Not reachable with C-mode commands.</summary>
    Work,

    /// <summary>Holding area (H0–H511).</summary>
    Holding,

    /// <summary>Auxiliary area (A0–A959); A0–A447 are read-only.</summary>
    Auxiliary,

    /// <summary>Data memory (D0–D32767).</summary>
    Dm,

    /// <summary>Timer present values (T0–T4095); the word number is the timer number.</summary>
    Timer,

    /// <summary>Counter present values (C0–C4095); the word number is the counter number.</summary>
    Counter,

    /// <summary>Extended data memory (E0_0–EC_32767), addressed by bank and word.</summary>
    Em,
}
