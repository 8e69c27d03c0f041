namespace OmronHostLink.Transports;

/// <summary>
/// Line settings of a serial port. The defaults are those of an Omron PLC's Host Link port:
/// 9600 baud, 7 data bits, even parity, 2 stop bits, no flow control, DTR and RTS off.
/// </summary>
public sealed class SerialLineSettings
{
    private static readonly int[] SupportedBaudRates =
        [300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

    /// <summary>
    /// The device: <c>COM3</c> on Windows; <c>/dev/ttyUSB0</c>, <c>/dev/ttyS0</c>, <c>/dev/pts/5</c> or a symbolic
    /// link to one (such as <c>/tmp/ttyV0</c> made by socat) on Linux.
    /// </summary>
    public string PortName { get; set; } = "";

    /// <summary>Line speed in bits per second; one of the standard rates 300 to 230400. Default 9600.</summary>
    public int BaudRate { get; set; } = 9600;

    /// <summary>Data bits per character: 7 (the Host Link default) or 8.</summary>
    public int DataBits { get; set; } = 7;

    /// <summary>Parity bit. Default <see cref="SerialParity.Even"/>.</summary>
    public SerialParity Parity { get; set; } = SerialParity.Even;

    /// <summary>Stop bits. Default <see cref="SerialStopBits.Two"/>.</summary>
    public SerialStopBits StopBits { get; set; } = SerialStopBits.Two;

    /// <summary>Flow control. Default <see cref="SerialHandshake.None"/>.</summary>
    public SerialHandshake Handshake { get; set; } = SerialHandshake.None;

    /// <summary>
    /// Raise DTR once the port is open. Off by default: pseudo-terminals reject the modem-control request,
    /// and when it is asked for and refused, opening fails.
    /// </summary>
    public bool DtrEnable { get; set; }

    /// <summary>
    /// Raise RTS once the port is open. Off by default, for the same reason as <see cref="DtrEnable"/>.
    /// Cannot be combined with <see cref="SerialHandshake.RequestToSend"/>, where the driver controls RTS.
    /// </summary>
    public bool RtsEnable { get; set; }

    /// <summary>Bits on the wire per character: 1 start bit + data bits + parity bit (if any) + stop bits (7E2 = 11).</summary>
    public int BitsPerCharacter => 1 + DataBits + (Parity == SerialParity.None ? 0 : 1) + (int)StopBits;

    /// <summary>
    /// Time to transmit one character, <see cref="BitsPerCharacter"/> / <see cref="BaudRate"/>, rounded up to the
    /// next 100 ns tick so that deadlines derived from it are never too short. Zero when <see cref="BaudRate"/> is not positive.
    /// </summary>
    public TimeSpan CharacterTime => BaudRate <= 0
        ? TimeSpan.Zero
        : TimeSpan.FromTicks((BitsPerCharacter * TimeSpan.TicksPerSecond + BaudRate - 1) / BaudRate);

    /// <summary>Checks that the settings can be applied, naming the offending property when they cannot.</summary>
    /// <exception cref="ArgumentException">A setting is out of range or two settings contradict each other.</exception>
    public void Validate()
    {
        if (string.IsNullOrWhiteSpace(PortName))
        {
            throw new ArgumentException(
                "SerialLineSettings.PortName is empty; set it to the serial device, e.g. COM3 or /dev/ttyUSB0.", nameof(PortName));
        }

        if (PortName.IndexOf('\0') >= 0)
        {
            throw new ArgumentException("SerialLineSettings.PortName contains a NUL character.", nameof(PortName));
        }

        if (Array.IndexOf(SupportedBaudRates, BaudRate) < 0)
        {
            throw new ArgumentException(
                $"SerialLineSettings.BaudRate {BaudRate} is not a supported standard rate; use one of {string.Join(", ", SupportedBaudRates)}.",
                nameof(BaudRate));
        }

        if (DataBits is not (7 or 8))
        {
            throw new ArgumentException(
                $"SerialLineSettings.DataBits must be 7 or 8; it was {DataBits}.", nameof(DataBits));
        }

        if (Parity is not (SerialParity.None or SerialParity.Even or SerialParity.Odd))
        {
            throw new ArgumentException(
                $"SerialLineSettings.Parity {(int)Parity} is not a SerialParity value (None, Even or Odd).", nameof(Parity));
        }

        if (StopBits is not (SerialStopBits.One or SerialStopBits.Two))
        {
            throw new ArgumentException(
                $"SerialLineSettings.StopBits {(int)StopBits} is not a SerialStopBits value (One or Two).", nameof(StopBits));
        }

        if (Handshake is not (SerialHandshake.None or SerialHandshake.RequestToSend or SerialHandshake.XOnXOff))
        {
            throw new ArgumentException(
                $"SerialLineSettings.Handshake {(int)Handshake} is not a SerialHandshake value (None, RequestToSend or XOnXOff).",
                nameof(Handshake));
        }

        if (RtsEnable && Handshake == SerialHandshake.RequestToSend)
        {
            throw new ArgumentException(
                "SerialLineSettings.RtsEnable cannot be set when Handshake is RequestToSend: the driver controls RTS.", nameof(RtsEnable));
        }
    }

    /// <summary>A copy, so that a transport is not changed by later edits of the caller's instance.</summary>
    internal SerialLineSettings Clone() => (SerialLineSettings)MemberwiseClone();

    /// <summary>Returns the settings in the usual short form, e.g. "/dev/ttyUSB0 9600 7E2".</summary>
    /// <returns>The port name, baud rate, data bits, parity letter and stop bits.</returns>
    public override string ToString()
    {
        char parity = Parity switch
        {
            SerialParity.None => 'N',
            SerialParity.Even => 'E',
            SerialParity.Odd => 'O',
            _ => '?',
        };
        string handshake = Handshake switch
        {
            SerialHandshake.RequestToSend => " RTS/CTS",
            SerialHandshake.XOnXOff => " XON/XOFF",
            _ => "",
        };
        return $"{PortName} {BaudRate} {DataBits}{parity}{(int)StopBits}{handshake}";
    }
}
