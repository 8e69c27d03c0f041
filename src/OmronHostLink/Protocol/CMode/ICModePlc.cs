namespace OmronHostLink.Protocol.CMode;

/// <summary>
/// The PLC side a C-mode command executes against: memory, mode, errors and the state a command keeps per unit (the
/// QQMR registration). The simulator's <c>VirtualPlc</c> implements it; the command table's rows execute against it,
/// so a command's PLC-side behaviour lives in its row, not in the simulator.
/// </summary>
internal interface ICModePlc
{
    /// <summary>The operating mode (SC changes it, MS reports it).</summary>
    PlcMode Mode { get; set; }

    /// <summary>The FAL/FALS message MS reports, or null.</summary>
    string? FalMessage { get; }

    /// <summary>The low byte of the MS status word.</summary>
    byte StatusLowByte { get; }

    /// <summary>The two words of error information MF reports.</summary>
    PlcErrorInfo Errors { get; }

    /// <summary>The model code MM reports.</summary>
    byte ModelCode { get; }

    /// <summary>Reads a word (EM: of <paramref name="bank"/>).</summary>
    ushort ReadWord(PlcArea area, int word, int bank);

    /// <summary>Writes a word (EM: of <paramref name="bank"/>).</summary>
    void WriteWord(PlcArea area, int word, ushort value, int bank);

    /// <summary>A timer's or counter's completion flag.</summary>
    bool GetFlag(PlcArea area, int number);

    /// <summary>Sets or clears a completion flag.</summary>
    void SetFlag(PlcArea area, int number, bool value);

    /// <summary>Sets or clears one bit.</summary>
    void SetBit(PlcArea area, int word, int bit, bool value);

    /// <summary>Forces one bit on or off.</summary>
    void ForceBit(PlcArea area, int word, int bit, bool set);

    /// <summary>Releases one forced bit.</summary>
    void ReleaseForced(PlcArea area, int word, int bit);

    /// <summary>Releases every forced bit.</summary>
    void ReleaseAllForced();

    /// <summary>Clears the error information.</summary>
    void ClearErrors();

    /// <summary>State a command keeps for <paramref name="unit"/> under <paramref name="key"/> (null when none; a restart loses it).</summary>
    object? GetUnitState(int unit, string key);

    /// <summary>Keeps state for <paramref name="unit"/> under <paramref name="key"/> until replaced or the PLC restarts.</summary>
    void SetUnitState(int unit, string key, object? value);
}
