using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>
/// Where a <see cref="PlcAddress"/> lies in FINS terms (memory area code, word, bit), and back: which PLC area, word
/// and EM bank a FINS area code and word address name. The host maps one way, a PLC (the simulator) the other.
/// </summary>
internal static class FinsAddressing
{
    /// <summary>The word a word address (or the word of a bit address) names.</summary>
    public static FinsMemoryAddress Word(PlcAddress a) => a.Area switch
    {
        PlcArea.Timer => new FinsMemoryAddress(FinsMemoryArea.TimerCounterPv, FinsMemoryArea.TimerAddress(a.Word)),
        PlcArea.Counter => new FinsMemoryAddress(FinsMemoryArea.TimerCounterPv, FinsMemoryArea.CounterAddress(a.Word)),
        PlcArea.Link => new FinsMemoryAddress(FinsMemoryArea.WordCode(FinsAreaKind.Cio, 0), PlcAreaInfo.CioAlias(a.Area, a.Word).Word),
        _ => new FinsMemoryAddress(FinsMemoryArea.WordCode(Kind(a.Area), a.Bank), a.Word),
    };

    /// <summary>The bit a bit address names.</summary>
    public static FinsMemoryAddress Bit(PlcAddress a) => a.Area switch
    {
        PlcArea.Timer => new FinsMemoryAddress(FinsMemoryArea.TimerCounterFlag, FinsMemoryArea.TimerAddress(a.Word)),
        PlcArea.Counter => new FinsMemoryAddress(FinsMemoryArea.TimerCounterFlag, FinsMemoryArea.CounterAddress(a.Word)),
        PlcArea.Link => new FinsMemoryAddress(FinsMemoryArea.BitCode(FinsAreaKind.Cio, 0), PlcAreaInfo.CioAlias(a.Area, a.Word).Word, a.Bit),
        _ => new FinsMemoryAddress(FinsMemoryArea.BitCode(Kind(a.Area), a.Bank), a.Word, a.Bit),
    };

    /// <summary>A bit for bit addresses and timer/counter flags, otherwise the word.</summary>
    public static FinsMemoryAddress Item(PlcAddress a)
        => a.IsBit || a.Area is PlcArea.Timer or PlcArea.Counter ? Bit(a) : Word(a);

    private static FinsAreaKind Kind(PlcArea area) => area switch
    {
        PlcArea.Cio => FinsAreaKind.Cio,
        PlcArea.Work => FinsAreaKind.Work,
        PlcArea.Holding => FinsAreaKind.Holding,
        PlcArea.Auxiliary => FinsAreaKind.Auxiliary,
        PlcArea.Dm => FinsAreaKind.Dm,
        PlcArea.Em => FinsAreaKind.Em,
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "No FINS area for this area."),
    };

    /// <summary>
    /// The PLC area, word (or timer/counter number) and EM bank that <paramref name="areaCode"/> and
    /// <paramref name="finsWord"/> name: word and bit access of CIO, W, H, A, DM and EM banks 0–C, the EM current
    /// bank, timer/counter present values and completion flags (counter <c>n</c> at 0x8000 + <c>n</c>).
    /// </summary>
    /// <param name="areaCode">The FINS area code.</param>
    /// <param name="finsWord">The word address of the FINS address.</param>
    /// <param name="currentEmBank">The bank the EM current-bank codes (98, 0A) stand for.</param>
    /// <param name="area">The PLC area.</param>
    /// <param name="word">The word, or the timer/counter number.</param>
    /// <param name="bank">The EM bank; 0 for other areas.</param>
    /// <returns>False for an area code this library does not map (forced-status areas, task flags, registers).</returns>
    public static bool TryLocate(byte areaCode, int finsWord, int currentEmBank, out PlcArea area, out int word, out int bank)
    {
        word = finsWord;
        bank = 0;
        switch (areaCode)
        {
            case FinsMemoryArea.CioWord or FinsMemoryArea.CioBit:
                area = PlcArea.Cio;
                return true;
            case FinsMemoryArea.WorkWord or FinsMemoryArea.WorkBit:
                area = PlcArea.Work;
                return true;
            case FinsMemoryArea.HoldingWord or FinsMemoryArea.HoldingBit:
                area = PlcArea.Holding;
                return true;
            case FinsMemoryArea.AuxiliaryWord or FinsMemoryArea.AuxiliaryBit:
                area = PlcArea.Auxiliary;
                return true;
            case FinsMemoryArea.DmWord or FinsMemoryArea.DmBit:
                area = PlcArea.Dm;
                return true;
            case FinsMemoryArea.EmCurrentBankWord or FinsMemoryArea.EmCurrentBankBit:
                area = PlcArea.Em;
                bank = currentEmBank;
                return true;
            case >= FinsMemoryArea.EmBank0Word and <= FinsMemoryArea.EmBank0Word + FinsMemoryArea.MaxEmBank:
                area = PlcArea.Em;
                bank = areaCode - FinsMemoryArea.EmBank0Word;
                return true;
            case >= FinsMemoryArea.EmBank0Bit and <= FinsMemoryArea.EmBank0Bit + FinsMemoryArea.MaxEmBank:
                area = PlcArea.Em;
                bank = areaCode - FinsMemoryArea.EmBank0Bit;
                return true;
            case FinsMemoryArea.TimerCounterPv or FinsMemoryArea.TimerCounterFlag:
                bool counter = finsWord >= FinsMemoryArea.CounterAddressOffset;
                area = counter ? PlcArea.Counter : PlcArea.Timer;
                word = counter ? finsWord - FinsMemoryArea.CounterAddressOffset : finsWord;
                return true;
            default:
                area = default;
                return false;
        }
    }
}
