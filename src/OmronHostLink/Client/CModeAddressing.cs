using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>Where a <see cref="PlcAddress"/> lies in C-mode terms.</summary>
internal static class CModeAddressing
{
    public static (CModeArea Area, int Begin) Map(PlcAddress address) => address.Area switch
    {
        PlcArea.Cio => (CModeArea.Cio, address.Word),
        PlcArea.Holding => (CModeArea.Holding, address.Word),
        PlcArea.Auxiliary => (CModeArea.Auxiliary, address.Word),
        PlcArea.Dm => (CModeArea.Dm, address.Word),
        PlcArea.Timer => (CModeArea.TimerCounterPv, address.Word),
        PlcArea.Counter => (CModeArea.TimerCounterPv, 2048 + address.Word),
        PlcArea.Em => (CModeArea.Em, address.Word),
        _ => throw new ArgumentException($"{address} is in the work area, which C-mode cannot reach; use FINS.", nameof(address)),
    };
}
