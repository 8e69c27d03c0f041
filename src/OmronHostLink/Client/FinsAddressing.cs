using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>Where a <see cref="PlcAddress"/> lies in FINS terms (memory area code, word, bit).</summary>
internal static class FinsAddressing
{
    /// <summary>The word a word address (or the word of a bit address) names.</summary>
    public static FinsMemoryAddress Word(PlcAddress a) => a.Area switch
    {
        PlcArea.Timer => new FinsMemoryAddress(FinsMemoryArea.TimerCounterPv, FinsMemoryArea.TimerAddress(a.Word)),
        PlcArea.Counter => new FinsMemoryAddress(FinsMemoryArea.TimerCounterPv, FinsMemoryArea.CounterAddress(a.Word)),
        _ => new FinsMemoryAddress(FinsMemoryArea.WordCode(Kind(a.Area), a.Bank), a.Word),
    };

    /// <summary>The bit a bit address names.</summary>
    public static FinsMemoryAddress Bit(PlcAddress a) => a.Area switch
    {
        PlcArea.Timer => new FinsMemoryAddress(FinsMemoryArea.TimerCounterFlag, FinsMemoryArea.TimerAddress(a.Word)),
        PlcArea.Counter => new FinsMemoryAddress(FinsMemoryArea.TimerCounterFlag, FinsMemoryArea.CounterAddress(a.Word)),
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
}
