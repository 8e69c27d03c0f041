using System.Runtime.InteropServices;

namespace OmronHostLink.Com;

/// <summary>The events of a watch (the IDL's <c>IPlcEvents</c> dispinterface), raised on the thread that called <c>Watch</c>.</summary>
[ComVisible(true)]
[Guid("EE9685BD-0A5C-4A9F-8D94-EAD792FAEB77")]
[InterfaceType(ComInterfaceType.InterfaceIsIDispatch)]
public interface IPlcEvents
{
    /// <summary>A watched tag's value changed; after <c>Watch</c> every tag is reported once.</summary>
    [DispId(1)]
    void ValueChanged(string tag, object value);

    /// <summary>The watch cannot read: <paramref name="number"/> is the <c>Err.Number</c> the read failed with.</summary>
    [DispId(2)]
    void ConnectionLost(int number, string description);

    /// <summary>The watch reads again after <paramref name="outageSeconds"/>.</summary>
    [DispId(3)]
    void ConnectionRestored(double outageSeconds);
}

/// <summary>The handler of <see cref="IPlcEvents.ValueChanged"/>.</summary>
public delegate void ValueChangedHandler(string tag, object value);

/// <summary>The handler of <see cref="IPlcEvents.ConnectionLost"/>.</summary>
public delegate void ConnectionLostHandler(int number, string description);

/// <summary>The handler of <see cref="IPlcEvents.ConnectionRestored"/>.</summary>
public delegate void ConnectionRestoredHandler(double outageSeconds);
