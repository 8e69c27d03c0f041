using System.IO.Ports;

namespace OmronHostLink.Transports;

/// <summary>A serial port on <see cref="SerialPort"/>; only its <see cref="SerialPort.BaseStream"/> carries data.</summary>
/// <remarks>
/// A pseudo-terminal is opened with 8 data bits and no parity, the framing it holds whatever is asked (some kernels
/// refuse to change it once the pty's first user has closed it); its baud rate and stop bits are set as asked, which
/// a pty accepts and ignores.
/// </remarks>
internal sealed class SystemSerialPort : ISerialPort
{
    private readonly SerialPort _port;

    private SystemSerialPort(SerialLineSettings settings, bool pseudoTerminal)
    {
        IsPseudoTerminal = pseudoTerminal;
        PortName = settings.PortName;
        _port = new SerialPort
        {
            PortName = settings.PortName,
            BaudRate = settings.BaudRate,
            DataBits = pseudoTerminal ? 8 : settings.DataBits,
            Parity = pseudoTerminal ? Parity.None : ToParity(settings.Parity),
            StopBits = settings.StopBits == SerialStopBits.Two ? StopBits.Two : StopBits.One,
            Handshake = settings.Handshake switch
            {
                SerialHandshake.RequestToSend => Handshake.RequestToSend,
                SerialHandshake.XOnXOff => Handshake.XOnXOff,
                _ => Handshake.None,
            },

            // DTR and RTS stay off (the defaults): a pseudo-terminal refuses modem-control requests.
            // Reads wait for the first byte and return what has come (the link's pump never cancels them); a write
            // held by flow control fails after WriteTimeout on Windows instead of blocking the link for ever.
            ReadTimeout = SerialPort.InfiniteTimeout,
            WriteTimeout = WriteTimeoutFor(settings),
        };
    }

    public string PortName { get; }

    public bool IsPseudoTerminal { get; }

    public Stream BaseStream => _port.BaseStream;

    /// <summary>Creates the port (closed) for <paramref name="settings"/>.</summary>
    /// <exception cref="ArgumentException">System.IO.Ports refuses the name (on Windows: one starting with <c>\\</c>).</exception>
    public static ISerialPort Create(SerialLineSettings settings) => new SystemSerialPort(settings, PseudoTerminal.Is(settings.PortName));

    public void Open() => _port.Open();

    public void SetDtr(bool on) => _port.DtrEnable = on;

    public void SetRts(bool on) => _port.RtsEnable = on;

    public void Dispose() => _port.Dispose();

    /// <summary>Time for the longest Host Link frame four times over at the line's speed, and never under two seconds.</summary>
    internal static int WriteTimeoutFor(SerialLineSettings settings)
    {
        double frameMs = 4 * (Protocol.FrameReader.MaxFrameLength + 8) * settings.BitsPerCharacter * 1000.0 / settings.BaudRate;
        return (int)Math.Max(2000, Math.Ceiling(frameMs));
    }

    private static Parity ToParity(SerialParity parity) => parity switch
    {
        SerialParity.Even => Parity.Even,
        SerialParity.Odd => Parity.Odd,
        _ => Parity.None,
    };
}
