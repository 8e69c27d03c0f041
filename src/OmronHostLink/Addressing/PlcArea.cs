namespace OmronHostLink;

/// <summary>A memory area of an Omron PLC, as named in CX-Programmer (CS/CJ names; older C-series names map onto them).</summary>
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

    /// <summary>
    /// The LR (link relay) area of C-series PLCs (<c>LR0</c>–<c>LR199</c>), read with C-mode RL and written with WL. On
    /// CS/CJ it is CIO 1000–1199 (LR <c>n</c> is CIO 1000 + <c>n</c>); on older models it is an area of its own.
    /// </summary>
    Link,
}
