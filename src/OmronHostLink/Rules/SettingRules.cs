using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// Every rule a client setting obeys, each in one place: the settings' validation, the option types' own checks, the
/// console and the hosts all ask here. Each check returns what is wrong in the writer's words (without the setting's
/// name, which the caller knows: a key path, a property or an option), or null when the value is good.
/// </summary>
/// <remarks>
/// The bottom layer: the rules use no other part of the library (a setting's enum is checked by its defined names, a
/// model name by <c>PlcModelProfile.CheckSetting</c>), so that the transports, the link and the protocol can use them.
/// </remarks>
internal static class SettingRules
{
    /// <summary>The highest unit number Host Link addresses.</summary>
    public const int MaxUnitNumber = HostLinkRules.MaxUnitNumber;

    /// <summary>The model setting that asks each unit its model (MM) instead of naming one.</summary>
    public const string AutoModel = "auto";

    /// <summary>The most times a read or a write may be repeated.</summary>
    public const int MaxRetries = 10;

    /// <summary>The highest FINS response wait, in units of 10 ms (the 4 bits of an FA frame's wait field).</summary>
    public const int MaxFinsResponseWait = 15;

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

    public static string? UnitNumber(int unit) => HostLinkRules.CheckUnitNumber(unit);

    public static string? Retries(int retries)
        => retries is < 0 or > MaxRetries ? $"{retries} is not 0-{MaxRetries}" : null;

    /// <summary>Whether a model setting is <see cref="AutoModel"/>.</summary>
    public static bool IsAutoModel(string? model) => string.Equals(model, AutoModel, StringComparison.OrdinalIgnoreCase);

    /// <summary>A value of an enum setting (command set, word order, parity, …): one of its named members.</summary>
    public static string? Defined<TEnum>(TEnum value)
        where TEnum : struct, Enum
        => Enum.IsDefined(typeof(TEnum), value)
            ? null
            : $"{Convert.ToInt64(value, CultureInfo.InvariantCulture).ToString(CultureInfo.InvariantCulture)} is not {Or(Enum.GetNames(typeof(TEnum)))}";

    public static string? FinsResponseWait(int wait)
        => wait is < 0 or > MaxFinsResponseWait ? $"{wait} is not 0-{MaxFinsResponseWait} (units of 10 ms)" : null;

    public static string? TurnaroundAllowance(TimeSpan value) => Positive(value, LongestTurnaround, "1 minute");

    public static string? SendInterval(TimeSpan value)
        => value < TimeSpan.Zero || value > LongestSendInterval
            ? $"{value.TotalMilliseconds.ToString("0.###", CultureInfo.InvariantCulture)} ms is not 0 to {LongestSendInterval.TotalSeconds.ToString(CultureInfo.InvariantCulture)} s"
            : null;

    /// <summary>The per-unit send intervals: each key a unit number, each gap a <see cref="SendInterval"/>.</summary>
    public static string? UnitSendIntervals(IDictionary<int, TimeSpan> intervals)
    {
        foreach (KeyValuePair<int, TimeSpan> unit in intervals)
        {
            if (HostLinkRules.CheckUnitNumber(unit.Key) is { } notUnit)
            {
                return $"names unit {unit.Key}: {notUnit}";
            }

            if (SendInterval(unit.Value) is { } tooLong)
            {
                return $"gives unit {unit.Key} {tooLong}";
            }
        }

        return null;
    }

    public static string? ConnectTimeout(TimeSpan value) => Positive(value, LongestConnectTimeout, "5 minutes");

    public static string? PortName(string name)
        => name.Trim().Length == 0 ? "is empty; write the serial device, e.g. COM3 or /dev/ttyUSB0"
            : name.IndexOf('\0') >= 0 ? "contains a NUL character"
            : null;

    public static string? TraceFile(string path)
        => path.Trim().Length == 0 ? "is empty; leave it unset for no trace"
            : path.IndexOf('\0') >= 0 ? "contains a NUL character"
            : null;

    public static string? BaudRate(int baud)
        => Array.IndexOf(StandardBaudRates, baud) < 0 ? $"{baud} is not a standard rate ({string.Join(", ", StandardBaudRates)})" : null;

    public static string? DataBits(int bits) => bits is >= MinDataBits and <= MaxDataBits ? null : $"{bits} is not {MinDataBits} or {MaxDataBits}";

    /// <summary>RTS is the driver's with RTS/CTS flow control (<paramref name="requestToSendHandshake"/>).</summary>
    public static string? RtsEnable(bool rts, bool requestToSendHandshake)
        => rts && requestToSendHandshake ? "cannot be true with Handshake RequestToSend: the driver controls RTS" : null;

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

    /// <summary><c>A, B or C</c>.</summary>
    private static string Or(string[] names)
        => names.Length < 2 ? string.Join("", names) : string.Join(", ", names, 0, names.Length - 1) + " or " + names[names.Length - 1];

    private static string? Positive(TimeSpan value, TimeSpan longest, string longestText)
        => value <= TimeSpan.Zero || value > longest
            ? $"{value.ToString("c", CultureInfo.InvariantCulture)} is not more than 0 and at most {longestText}"
            : null;
}
