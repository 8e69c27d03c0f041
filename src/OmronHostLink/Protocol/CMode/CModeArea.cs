namespace OmronHostLink.Protocol.CMode;

/// <summary>The memory areas C-mode read and write commands reach, each with its own header pair.</summary>
internal enum CModeArea
{
    /// <summary>CIO (IR/SR) area: RR / WR, words 0000-6143.</summary>
    Cio,

    /// <summary>LR area (CIO 1000-1199 on CS/CJ): RL / WL, words 0000-0199.</summary>
    Lr,

    /// <summary>HR area: RH / WH, words 0000-0511.</summary>
    Holding,

    /// <summary>Timer/counter present values: RC / WC; timers 0000-2047, counters 2048-4095 (C n = 2048 + n).</summary>
    TimerCounterPv,

    /// <summary>Timer/counter completion flags: RG (read only, one character per point).</summary>
    TimerCounterStatus,

    /// <summary>DM area: RD / WD, words 0000-9999.</summary>
    Dm,

    /// <summary>AR area: RJ / WJ; reads A000-A959, writes A448-A959 only.</summary>
    Auxiliary,

    /// <summary>EM area: RE / WE with a bank number 00-0C, words 0000-9999.</summary>
    Em,
}
