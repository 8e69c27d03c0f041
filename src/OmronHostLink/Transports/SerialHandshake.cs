namespace OmronHostLink.Transports;

/// <summary>Flow control on a serial line.</summary>
public enum SerialHandshake
{
    /// <summary>No flow control (the Omron Host Link default).</summary>
    None,

    /// <summary>Hardware flow control: RTS/CTS.</summary>
    RequestToSend,

    /// <summary>Software flow control: XON (0x11) / XOFF (0x13) characters.</summary>
    XOnXOff,
}
