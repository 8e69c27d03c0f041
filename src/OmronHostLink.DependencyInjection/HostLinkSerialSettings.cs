using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection;

/// <summary>
/// The serial line of a Host Link client. With <see cref="PortName"/>, a serial port on this machine; with
/// <see cref="HostLinkClientSettings.Tcp"/> instead, the line behind the serial-device server, whose
/// <see cref="BaudRate"/>, <see cref="DataBits"/>, <see cref="Parity"/> and <see cref="StopBits"/> set the frame
/// deadlines (the server's own port settings must match them). Unset values take Omron's defaults: 9600 7E2.
/// </summary>
public sealed class HostLinkSerialSettings
{
    /// <summary>The local port: <c>COM3</c>, <c>/dev/ttyUSB0</c>, or any device path or link to one.</summary>
    public string? PortName { get; set; }

    /// <summary>Line speed in bits per second, one of the standard rates 300-230400. Default 9600.</summary>
    public int? BaudRate { get; set; }

    /// <summary>Data bits per character, 7 or 8. Default 7.</summary>
    public int? DataBits { get; set; }

    /// <summary>Parity bit: None, Even or Odd. Default Even.</summary>
    public SerialParity? Parity { get; set; }

    /// <summary>Stop bits: One or Two (also written 1 or 2). Default Two.</summary>
    public SerialStopBits? StopBits { get; set; }

    /// <summary>Flow control of a local port: None, RequestToSend or XOnXOff. Default None.</summary>
    public SerialHandshake? Handshake { get; set; }

    /// <summary>Raise DTR on a local port once it is open. Default false.</summary>
    public bool? DtrEnable { get; set; }

    /// <summary>Raise RTS on a local port once it is open (not with RequestToSend handshake). Default false.</summary>
    public bool? RtsEnable { get; set; }
}
