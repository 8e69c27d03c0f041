using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The PLC side a FINS command executes against: what a C-mode command uses (<see cref="ICModePlc"/>) and the bits of
/// EM banks, the clock and the CPU Unit's name. The simulator's <c>VirtualPlc</c> implements it; each row of
/// <see cref="FinsCommandTable"/> executes against it, so a command's PLC-side behaviour lives in its row.
/// </summary>
internal interface IFinsPlc : ICModePlc
{
    /// <summary>Reads one bit (EM: of <paramref name="bank"/>).</summary>
    bool GetBit(PlcArea area, int word, int bit, int bank);

    /// <summary>Sets or clears one bit (EM: of <paramref name="bank"/>).</summary>
    void SetBit(PlcArea area, int word, int bit, bool value, int bank);

    /// <summary>The PLC's clock (0701 reads it, 0702 sets it).</summary>
    DateTime Clock { get; set; }

    /// <summary>The CPU Unit's model and version, as 0501 reports them.</summary>
    FinsCpuUnitData UnitData { get; }
}
