using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// Where a <see cref="PlcAddress"/> lies in C-mode terms, and back: which PLC word a C-mode entry (or a forced bit's
/// word) names. The host maps one way, a PLC (the simulator) the other.
/// </summary>
internal static class CModeAddressing
{
    /// <summary>The C-mode area that carries <paramref name="area"/>; timers and counters share the timer/counter area.</summary>
    /// <exception cref="ArgumentException">The work area, which C-mode cannot reach.</exception>
    public static CModeArea AreaOf(PlcArea area) => area switch
    {
        PlcArea.Cio => CModeArea.Cio,
        PlcArea.Holding => CModeArea.Holding,
        PlcArea.Auxiliary => CModeArea.Auxiliary,
        PlcArea.Dm => CModeArea.Dm,
        PlcArea.Timer or PlcArea.Counter => CModeArea.TimerCounterPv,
        PlcArea.Em => CModeArea.Em,
        PlcArea.Link => CModeArea.Lr,
        _ => throw new ArgumentException($"The {PlcAreaInfo.Name(area)} is not reachable with C-mode; {CommandSetAdvice.UseFins()}.", nameof(area)),
    };

    /// <summary>The C-mode area and entry of a word address (counter <c>n</c> is entry 2048 + <c>n</c>).</summary>
    /// <exception cref="ArgumentException">The address is in the work area, which C-mode cannot reach.</exception>
    public static (CModeArea Area, int Begin) Map(PlcAddress address) => Map(address, null);

    /// <summary>
    /// As <see cref="Map(PlcAddress)"/>, on <paramref name="model"/>: where timers and counters share one TC number
    /// space (the older families), counter <c>n</c> is entry <c>n</c>, as timer <c>n</c> is.
    /// </summary>
    public static (CModeArea Area, int Begin) Map(PlcAddress address, PlcModelProfile? model)
    {
        if (model is { SharesTimerCounterNumbers: true } && address.Area == PlcArea.Counter)
        {
            return (CModeArea.TimerCounterPv, address.Word);
        }

        if (address.Area == PlcArea.Work)
        {
            throw new ArgumentException($"{address} is in the work area, which C-mode cannot reach; {CommandSetAdvice.UseFins()}.", nameof(address));
        }

        return (AreaOf(address.Area), address.Area == PlcArea.Counter ? CModeAreaInfo.CounterOffset + address.Word : address.Word);
    }

    /// <summary>The PLC word (or timer/counter) that entry <paramref name="entry"/> of a C-mode area names.</summary>
    public static (PlcArea Area, int Word) Locate(CModeArea area, int entry) => area switch
    {
        CModeArea.Cio => (PlcArea.Cio, entry),
        CModeArea.Lr => (PlcArea.Cio, CModeAreaInfo.LrCioStart + entry),
        CModeArea.Holding => (PlcArea.Holding, entry),
        CModeArea.TimerCounterPv or CModeArea.TimerCounterStatus => entry < CModeAreaInfo.CounterOffset
            ? (PlcArea.Timer, entry)
            : (PlcArea.Counter, entry - CModeAreaInfo.CounterOffset),
        CModeArea.Dm => (PlcArea.Dm, entry),
        CModeArea.Auxiliary => (PlcArea.Auxiliary, entry),
        CModeArea.Em => (PlcArea.Em, entry),
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown C-mode area."),
    };

    /// <summary>The PLC word (or timer/counter) a KS, KR or FK command names in <paramref name="area"/>.</summary>
    public static (PlcArea Area, int Word) Locate(ForceArea area, int word) => area switch
    {
        ForceArea.Cio => (PlcArea.Cio, word),
        ForceArea.Lr => (PlcArea.Cio, CModeAreaInfo.LrCioStart + word),
        ForceArea.Holding => (PlcArea.Holding, word),
        ForceArea.Auxiliary => (PlcArea.Auxiliary, word),
        ForceArea.Timer => (PlcArea.Timer, word),
        ForceArea.Counter => (PlcArea.Counter, word),
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown force area."),
    };
}
