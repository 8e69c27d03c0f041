namespace OmronHostLink.Transports;

/// <summary>
/// Line settings of a serial port. The defaults are those of an Omron PLC's Host Link port:
/// 9600 baud, 7 data bits, even parity, 2 stop bits, no flow control, DTR and RTS off.
/// </summary>
public sealed class SerialLineSettings
{
    /// <summary>The line speed of an Omron Host Link port as it leaves the factory, and of every default here.</summary>
    internal const int DefaultBaudRate = 9600;

    /// <summary>
    /// The device: <c>COM3</c> on Windows; <c>/dev/ttyUSB0</c>, <c>/dev/ttyS0</c>, <c>/dev/pts/5</c> or a symbolic
    /// link to one (such as <c>/tmp/ttyV0</c> made by socat) on Linux.
    /// </summary>
    public string PortName { get; set; } = "";

    /// <summary>Line speed in bits per second; one of the standard rates 300 to 230400. Default 9600.</summary>
    public int BaudRate { get; set; } = DefaultBaudRate;

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
        // The rules are the client settings' own (SettingRules): one check, whichever way the values arrive.
        Check(nameof(PortName), SettingRules.PortName(PortName ?? ""));
        Check(nameof(BaudRate), SettingRules.BaudRate(BaudRate));
        Check(nameof(DataBits), SettingRules.DataBits(DataBits));
        Check(nameof(Parity), SettingRules.Defined(Parity));
        Check(nameof(StopBits), SettingRules.Defined(StopBits));
        Check(nameof(Handshake), SettingRules.Defined(Handshake));
        Check(nameof(RtsEnable), SettingRules.RtsEnable(RtsEnable, Handshake == SerialHandshake.RequestToSend));
    }

    private static void Check(string property, string? problem)
    {
        if (problem is not null)
        {
            throw new ArgumentException($"{nameof(SerialLineSettings)}.{property} {problem}.", property);
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
