using System.Globalization;
using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// Every rule a client setting obeys, each in one place: the settings' validation, the option types' own checks, the
/// console and the hosts all ask here. Each check returns what is wrong in the writer's words (without the setting's
/// name, which the caller knows: a key path, a property or an option), or null when the value is good.
/// </summary>
internal static class SettingRules
{
    /// <summary>The highest unit number Host Link addresses.</summary>
    public const int MaxUnitNumber = HostLinkUnit.MaxUnitNumber;

    /// <summary>The most times a read or a write may be repeated.</summary>
    public const int MaxRetries = 10;

    /// <summary>The highest FINS response wait, in units of 10 ms.</summary>
    public const int MaxFinsResponseWait = Protocol.Fins.FinsHeader.MaxResponseWait;

    /// <summary>The longest turnaround allowance.</summary>
    public static readonly TimeSpan LongestTurnaround = TimeSpan.FromMinutes(1);

    /// <summary>The longest send interval, of a link or of a unit.</summary>
    public static readonly TimeSpan LongestSendInterval = TimeSpan.FromSeconds(10);

    /// <summary>The most data bits a character may have; the fewest is 7 (Host Link's own 7E2).</summary>
    public const int MaxDataBits = 8;

    /// <summary>The fewest data bits a character may have.</summary>
    public const int MinDataBits = 7;

    /// <summary>The highest TCP port number.</summary>
    public const int MaxTcpPort = 65535;

    /// <summary>The longest TCP connection attempt.</summary>
    public static readonly TimeSpan LongestConnectTimeout = TimeSpan.FromMinutes(5);

    /// <summary>The line speeds a serial port (and the line behind a serial-device server) may run at.</summary>
    public static readonly int[] StandardBaudRates = [300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

    public static string? UnitNumber(int unit)
        => unit is < 0 or > MaxUnitNumber ? $"{unit} is not a unit number (0-{MaxUnitNumber})" : null;

    public static string? Retries(int retries)
        => retries is < 0 or > MaxRetries ? $"{retries} is not 0-{MaxRetries}" : null;

    /// <summary>A PLC model profile name, or <c>auto</c> (ask the PLC with MM).</summary>
    public static string? Model(string model)
        => string.Equals(model, UnitModels.Auto, StringComparison.OrdinalIgnoreCase) || PlcModelProfile.TryParse(model, out _)
            ? null
            : $"'{model}' is not a known PLC model; use one of {PlcModelProfile.KnownNames()}, or auto to ask the PLC (MM)";

    /// <summary>A Serial Communications Unit's Host Link-compatible device mode.</summary>
    public static string? CompatibleMode(HostLinkCompatibleMode value)
        => value is >= HostLinkCompatibleMode.ModeA and <= HostLinkCompatibleMode.ModeD ? null : $"{(int)value} is not ModeA, ModeB, ModeC or ModeD";

    public static string? FinsResponseWait(int wait)
        => wait is < 0 or > MaxFinsResponseWait ? $"{wait} is not 0-{MaxFinsResponseWait} (units of 10 ms)" : null;

    public static string? TurnaroundAllowance(TimeSpan value) => Positive(value, LongestTurnaround, "1 minute");

    public static string? SendInterval(TimeSpan value)
        => value < TimeSpan.Zero || value > LongestSendInterval
            ? $"{value.TotalMilliseconds.ToString("0.###", CultureInfo.InvariantCulture)} ms is not 0 to {LongestSendInterval.TotalSeconds.ToString(CultureInfo.InvariantCulture)} s"
            : null;

    public static string? ConnectTimeout(TimeSpan value) => Positive(value, LongestConnectTimeout, "5 minutes");

    public static string? CommandSet(HostLinkCommandSet value)
        => value is HostLinkCommandSet.CMode or HostLinkCommandSet.Fins ? null : $"{(int)value} is not CMode or Fins";

    public static string? WordOrder(WordOrder value)
        => value is OmronHostLink.WordOrder.LowWordFirst or OmronHostLink.WordOrder.HighWordFirst ? null : $"{(int)value} is not LowWordFirst or HighWordFirst";

    public static string? PortName(string name)
        => name.Trim().Length == 0 ? "is empty; write the serial device, e.g. COM3 or /dev/ttyUSB0"
            : name.IndexOf('\0') >= 0 ? "contains a NUL character"
            : null;

    public static string? BaudRate(int baud)
        => Array.IndexOf(StandardBaudRates, baud) < 0 ? $"{baud} is not a standard rate ({string.Join(", ", StandardBaudRates)})" : null;

    public static string? DataBits(int bits) => bits is >= MinDataBits and <= MaxDataBits ? null : $"{bits} is not {MinDataBits} or {MaxDataBits}";

    public static string? Parity(SerialParity value)
        => value is SerialParity.None or SerialParity.Even or SerialParity.Odd ? null : $"{(int)value} is not None, Even or Odd";

    public static string? StopBits(SerialStopBits value)
        => value is SerialStopBits.One or SerialStopBits.Two ? null : $"{(int)value} is not One or Two";

    public static string? Handshake(SerialHandshake value)
        => value is SerialHandshake.None or SerialHandshake.RequestToSend or SerialHandshake.XOnXOff ? null : $"{(int)value} is not None, RequestToSend or XOnXOff";

    /// <summary>RTS is the driver's with RTS/CTS flow control.</summary>
    public static string? RtsEnable(bool rts, SerialHandshake handshake)
        => rts && handshake == SerialHandshake.RequestToSend ? "cannot be true with Handshake RequestToSend: the driver controls RTS" : null;

    public static string? Host(string host)
        => host.Trim().Length == 0 ? "is empty; write the serial-device server's host name or address" : null;

    public static string? TcpPort(int port) => port is < 1 or > MaxTcpPort ? $"{port} is not a TCP port (1-{MaxTcpPort})" : null;

    /// <summary>Reads <c>host:port</c> (an IPv6 address in brackets: <c>[fd00::5]:4001</c>).</summary>
    public static bool TryParseEndpoint(string text, out string host, out int port, out string? error)
    {
        host = "";
        port = 0;
        error = null;
        if (text.IndexOf("://", StringComparison.Ordinal) >= 0)
        {
            error = $"'{text}' is a URL; write host:port without a scheme (e.g. 192.0.2.10:4001), or write a section with Host and Port";
            return false;
        }

        int colon = text.LastIndexOf(':');
        string h = colon > 0 ? text.Substring(0, colon).Trim() : "";
        string p = colon > 0 ? text.Substring(colon + 1).Trim() : "";
        if (h.StartsWith("[", StringComparison.Ordinal) && h.EndsWith("]", StringComparison.Ordinal))
        {
            h = h.Substring(1, h.Length - 2);
        }
        else if (h.IndexOf(':') >= 0)
        {
            error = $"'{text}': write an IPv6 address in brackets, e.g. [fd00::5]:4001";
            return false;
        }

        if (h.Length == 0 || p.Length == 0)
        {
            error = $"'{text}' is not host:port (e.g. 192.0.2.10:4001), or write a section with Host and Port";
            return false;
        }

        if (!int.TryParse(p, NumberStyles.None, CultureInfo.InvariantCulture, out int number) || TcpPort(number) is not null)
        {
            error = $"'{text}': the port '{p}' is not a number 1-{MaxTcpPort}";
            return false;
        }

        host = h;
        port = number;
        return true;
    }

    private static string? Positive(TimeSpan value, TimeSpan longest, string longestText)
        => value <= TimeSpan.Zero || value > longest
            ? $"{value.ToString("c", CultureInfo.InvariantCulture)} is not more than 0 and at most {longestText}"
            : null;
}
