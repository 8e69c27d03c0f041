using System.Globalization;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>Facts about each CS/CJ memory area, kept in one place so that parsing, formatting and range checks agree.</summary>
internal static class PlcAreaInfo
{
    /// <summary>EM banks 0x0–0xC exist on CS/CJ; later banks (CJ2) need other FINS area codes.</summary>
    public const int EmBankCount = 13;

    /// <summary>A0–A447 are written by the CPU only.</summary>
    public const int FirstWritableAuxiliaryWord = 448;

    public static bool IsDefined(PlcArea area) => area >= PlcArea.Cio && area <= PlcArea.Link;

    public static int Size(PlcArea area) => area switch
    {
        PlcArea.Cio => 6144,
        PlcArea.Work => 512,
        PlcArea.Holding => 512,
        PlcArea.Auxiliary => 960,
        PlcArea.Dm => 32768,
        PlcArea.Timer => 4096,
        PlcArea.Counter => 4096,
        PlcArea.Em => 32768,
        PlcArea.Link => CModeAreaInfo.Size(CModeArea.Lr),
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, $"{area} is not a PLC area."),
    };

    /// <summary>Words (or T/C numbers) reachable with C-mode, counted from 0 (W342 p128).</summary>
    public static int CModeLimit(PlcArea area) => area switch
    {
        PlcArea.Work => 0,
        PlcArea.Timer or PlcArea.Counter => CModeAreaInfo.CounterOffset,
        _ => CModeAreaInfo.Size(CModeAddressing.AreaOf(area)),
    };

    /// <summary>The C-mode command that would carry the transfer, so messages can name it.</summary>
    public static string CModeCommand(PlcArea area, bool forWrite)
    {
        if (area == PlcArea.Work)
        {
            return "(none)";
        }

        CModeArea cmode = CModeAddressing.AreaOf(area);
        return forWrite ? CModeAreaInfo.WriteHeader(cmode) : CModeAreaInfo.ReadHeader(cmode);
    }

    /// <summary>
    /// The CIO word an address of <paramref name="area"/> shares memory with on CS/CJ (LR <c>n</c> is CIO 1000 + <c>n</c>),
    /// or the address itself for other areas; FINS and the simulator's memory use it.
    /// </summary>
    public static (PlcArea Area, int Word) CioAlias(PlcArea area, int word) =>
        area == PlcArea.Link ? (PlcArea.Cio, CModeAreaInfo.LrCioStart + word) : (area, word);

    /// <summary>Timers and counters name a T/C, not a word of bits.</summary>
    public static bool AllowsBit(PlcArea area) => area is not (PlcArea.Timer or PlcArea.Counter);

    public static string Name(PlcArea area) => area switch
    {
        PlcArea.Cio => "CIO area",
        PlcArea.Work => "work area (W)",
        PlcArea.Holding => "holding area (H)",
        PlcArea.Auxiliary => "auxiliary area (A)",
        PlcArea.Dm => "DM area",
        PlcArea.Timer => "timer area",
        PlcArea.Counter => "counter area",
        PlcArea.Link => "LR area",
        _ => "EM area",
    };

    /// <summary>The area as the user would write its extent, e.g. "DM area (D0–D32767)".</summary>
    public static string Extent(PlcArea area, int bank) =>
        $"{Name(area)} ({Format(area, 0, -1, bank)}–{Format(area, Size(area) - 1, -1, bank)})";

    /// <summary>Canonical CX-Programmer spelling; also used to name computed addresses in messages.</summary>
    public static string Format(PlcArea area, int word, int bit, int bank)
    {
        var text = area switch
        {
            PlcArea.Cio => "CIO",
            PlcArea.Work => "W",
            PlcArea.Holding => "H",
            PlcArea.Auxiliary => "A",
            PlcArea.Dm => "D",
            PlcArea.Timer => "T",
            PlcArea.Counter => "C",
            PlcArea.Link => "LR",
            _ => "E" + bank.ToString("X", CultureInfo.InvariantCulture) + "_",
        } + word.ToString(CultureInfo.InvariantCulture);
        return bit < 0 ? text : text + "." + bit.ToString("00", CultureInfo.InvariantCulture);
    }
}
