namespace OmronHostLink.Protocol.Fins;

/// <summary>The CS/CJ memory areas <see cref="FinsMemoryArea"/> maps to FINS area codes.</summary>
internal enum FinsAreaKind
{
    /// <summary>CIO area (word B0, bit 30).</summary>
    Cio,

    /// <summary>Work area WR (word B1, bit 31).</summary>
    Work,

    /// <summary>Holding area HR (word B2, bit 32).</summary>
    Holding,

    /// <summary>Auxiliary area AR (word B3, bit 33).</summary>
    Auxiliary,

    /// <summary>Data memory DM (word 82, bit 02).</summary>
    Dm,

    /// <summary>Timer/counter present values (word 89; no bit access).</summary>
    TimerCounterPv,

    /// <summary>Timer/counter completion flags (bit 09; no word access).</summary>
    TimerCounterFlag,

    /// <summary>Extended data memory, one bank (word A0–AC, bit 20–2C for banks 0–C).</summary>
    Em,

    /// <summary>Extended data memory, the current bank (word 98, bit 0A).</summary>
    EmCurrentBank,
}
