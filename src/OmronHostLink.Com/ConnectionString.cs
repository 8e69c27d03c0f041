using System.Globalization;

namespace OmronHostLink.Com;

/// <summary>
/// Reads the connection strings <c>Plc.Open</c> takes into the library's one settings type,
/// <see cref="HostLinkClientSettings"/>, whose checks name what is wrong:
/// <list type="bullet">
/// <item><c>COM3</c>, <c>COM3:9600</c>, <c>COM3:9600,E,7,2</c> — a local port, then speed, parity (E, O, N), data bits and
/// stop bits as MSComm's <c>Settings</c> wrote them; what is left out is Omron's default (9600, E, 7, 2).</item>
/// <item><c>tcp://192.0.2.10:4001</c> — a serial-device server (or the simulator).</item>
/// <item>then <c>;Key=Value</c> pairs of the client settings (<c>UnitNumber=3</c>, <c>CommandSet=Fins</c>,
/// <c>TurnaroundAllowance=500ms</c>, <c>ReadRetries=2</c>, <c>Serial:BaudRate=19200</c> for the line behind a server);
/// <c>Unit</c>, <c>BaudRate</c>, <c>Parity</c>, <c>DataBits</c> and <c>StopBits</c> may be written without their section.</item>
/// </list>
/// </summary>
internal static class ConnectionString
{
    private const string TcpScheme = "tcp://";

    private static readonly string[] SerialKeys = ["BaudRate", "Parity", "DataBits", "StopBits"];

    /// <summary>Reads <paramref name="text"/> into settings; a value the settings cannot use is kept for their <c>Validate</c>.</summary>
    /// <exception cref="FormatException">The text has no link, or a part that is not <c>Key=Value</c>.</exception>
    public static HostLinkClientSettings Parse(string text)
    {
        string[] parts = text.Split(';');
        string link = parts[0].Trim();
        if (link.Length == 0)
        {
            throw new FormatException($"The connection string '{text}' names no link: start it with a port (COM3:9600,E,7,2) or a server (tcp://host:port).");
        }

        var pairs = new List<KeyValuePair<string, string?>>();
        if (link.StartsWith(TcpScheme, StringComparison.OrdinalIgnoreCase))
        {
            pairs.Add(Pair("Tcp", link.Substring(TcpScheme.Length)));
        }
        else
        {
            ReadSerial(link, pairs);
        }

        foreach (string part in parts.Skip(1))
        {
            if (part.Trim().Length == 0)
            {
                continue;
            }

            int equals = part.IndexOf('=');
            if (equals <= 0)
            {
                throw new FormatException($"'{part.Trim()}' in the connection string is not Key=Value (as in UnitNumber=3 or CommandSet=Fins).");
            }

            pairs.Add(Pair(KeyOf(part.Substring(0, equals).Trim()), part.Substring(equals + 1).Trim()));
        }

        var settings = new HostLinkClientSettings();
        settings.Read(pairs);
        return settings;
    }

    /// <summary><c>COM3</c> or <c>COM3:9600,E,7,2</c>: the port, then MSComm's settings in their order.</summary>
    private static void ReadSerial(string link, List<KeyValuePair<string, string?>> pairs)
    {
        int colon = link.IndexOf(':');
        string port = colon < 0 ? link : link.Substring(0, colon).Trim();
        pairs.Add(Pair("Serial:PortName", port));
        if (colon < 0)
        {
            return;
        }

        string[] fields = link.Substring(colon + 1).Split(',');
        if (fields.Length > SerialKeys.Length)
        {
            throw new FormatException($"'{link}' has {fields.Length} line settings; write at most speed, parity, data bits and stop bits, as in COM3:9600,E,7,2.");
        }

        for (int i = 0; i < fields.Length; i++)
        {
            string value = fields[i].Trim();
            if (value.Length > 0)
            {
                pairs.Add(Pair("Serial:" + SerialKeys[i], SerialKeys[i] == "Parity" ? ParityName(value) : value));
            }
        }
    }

    /// <summary>MSComm's parity letters, as the settings name them; anything else is left for the settings to refuse.</summary>
    public static string ParityName(string value) => value.Trim().ToUpperInvariant() switch
    {
        "E" => "Even",
        "O" => "Odd",
        "N" => "None",
        _ => value,
    };

    private static string KeyOf(string key)
    {
        if (key.Equals("Unit", StringComparison.OrdinalIgnoreCase))
        {
            return "UnitNumber";
        }

        return SerialKeys.Any(k => k.Equals(key, StringComparison.OrdinalIgnoreCase)) ? "Serial:" + key : key;
    }

    private static KeyValuePair<string, string?> Pair(string key, string value) => new(key, value);

    /// <summary>The settings' problems as one message for <c>Err.Description</c>, or null when there are none.</summary>
    public static string? Problems(HostLinkClientSettings settings, string what)
    {
        IReadOnlyList<HostLinkSettingsProblem> problems = settings.Validate();
        return problems.Count == 0
            ? null
            : string.Format(CultureInfo.InvariantCulture, "{0} cannot be used: {1}.", what, string.Join("; ", problems));
    }
}
