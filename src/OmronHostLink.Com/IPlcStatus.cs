using System.Runtime.InteropServices;

namespace OmronHostLink.Com;

/// <summary>A PLC's status as <c>Plc.ReadStatus</c> returns it (the IDL's <c>IPlcStatus</c>).</summary>
[ComVisible(true)]
[Guid("50076105-4D61-467B-8DF3-535AF7C03BE4")]
[InterfaceType(ComInterfaceType.InterfaceIsDual)]
public interface IPlcStatus
{
    /// <summary><c>PROGRAM</c>, <c>MONITOR</c> or <c>RUN</c>.</summary>
    [DispId(1)]
    string Mode { get; }

    /// <summary>The status word, or -1 when the PLC does not report one.</summary>
    [DispId(2)]
    int StatusWord { get; }

    /// <summary>The FAL/FALS message, or an empty string.</summary>
    [DispId(3)]
    string Message { get; }
}

/// <summary>The status object (the IDL's non-creatable <c>PlcStatus</c> class; internal, so regsvr32 does not register it as creatable).</summary>
[ComVisible(true)]
[Guid("D50B123D-B9AD-4632-8443-A8E53D09A3C9")]
[ClassInterface(ClassInterfaceType.None)]
internal sealed class PlcStatusInfo : IPlcStatus
{
    internal PlcStatusInfo(PlcStatus status)
    {
        Mode = ComValues.ModeName(status.Mode);
        StatusWord = status.StatusWord ?? -1;
        Message = status.Message ?? "";
    }

    /// <inheritdoc />
    public string Mode { get; }

    /// <inheritdoc />
    public int StatusWord { get; }

    /// <inheritdoc />
    public string Message { get; }
}
