using System.Globalization;
using Microsoft.Extensions.Options;
using OmronHostLink.DependencyInjection.Configuration;
using OmronHostLink.Transports;

namespace OmronHostLink.DependencyInjection.Validation;

/// <summary>
/// Checks a client's settings when the host starts and reports every problem at once, each starting with the
/// configuration path of its key (<c>HostLink:Clients:line1:Serial:BaudRate: 12345 is not a standard rate …</c>),
/// or with the client's name when it was set in code.
/// </summary>
internal sealed class HostLinkClientSettingsValidator : IValidateOptions<HostLinkClientSettings>
{
    private static readonly int[] StandardBaudRates = [300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

    private static readonly TimeSpan LongestTurnaround = TimeSpan.FromMinutes(1);

    private static readonly TimeSpan LongestConnectTimeout = TimeSpan.FromMinutes(5);

    /// <inheritdoc/>
    public ValidateOptionsResult Validate(string? name, HostLinkClientSettings options)
    {
        if (options is null)
        {
            return ValidateOptionsResult.Skip;
        }

        var problems = new List<SettingsProblem>(options.ReadProblems);
        CheckLink(options, problems);
        CheckSerial(options, problems);
        CheckTcp(options.Tcp, problems);
        CheckClient(options, problems);
        if (problems.Count == 0)
        {
            // Whatever the library itself refuses and the rules above missed still fails here, at start.
            problems.AddRange(HostLinkClientSettingsMapper.ProblemsTheLibraryFinds(options));
        }

        return problems.Count == 0
            ? ValidateOptionsResult.Success
            : ValidateOptionsResult.Fail(problems.Select(p => Describe(options.ConfigurationPath, name, p)));
    }

    /// <summary>
    /// <c>HostLink:Clients:line1:Serial:BaudRate: …</c> for configuration; <c>Host Link client "line1": Serial:BaudRate: …</c>
    /// for settings made in code only.
    /// </summary>
    private static string Describe(string? configurationPath, string? name, SettingsProblem problem)
    {
        if (configurationPath is null)
        {
            string client = string.IsNullOrEmpty(name) ? "The default Host Link client" : $"Host Link client \"{name}\"";
            return problem.Key.Length == 0 ? $"{client}: {problem.Message}" : $"{client}: {problem.Key}: {problem.Message}";
        }

        string path = configurationPath.Length == 0 || problem.Key.Length == 0
            ? configurationPath + problem.Key
            : configurationPath + ":" + problem.Key;
        return path.Length == 0 ? problem.Message : $"{path}: {problem.Message}";
    }

    private static void CheckLink(HostLinkClientSettings s, List<SettingsProblem> problems)
    {
        // A key that is written but could not be read still says which link was meant.
        bool serialPort = s.Serial.PortName is not null || problems.Any(p => p.IsAtOrBelow("Serial:PortName"));
        bool tcp = s.Tcp.Host is not null || s.Tcp.Port is not null || s.Tcp.ConnectTimeout is not null || problems.Any(p => p.IsAtOrBelow("Tcp"));
        if (serialPort && tcp)
        {
            problems.Add(new SettingsProblem("Tcp", "cannot be combined with Serial:PortName; a client uses either a local serial port or a serial-device server"));
        }
        else if (!serialPort && !tcp && !problems.Any(p => p.Key.Length == 0 || p.Key.Equals("Serial", StringComparison.OrdinalIgnoreCase)))
        {
            problems.Add(new SettingsProblem("", "no link is set; write Serial:PortName (a serial port such as COM3 or /dev/ttyUSB0) or Tcp (host:port of a serial-device server)"));
        }
    }

    private static void CheckSerial(HostLinkClientSettings settings, List<SettingsProblem> problems)
    {
        HostLinkSerialSettings s = settings.Serial;
        if (s.PortName is { } port && (port.Trim().Length == 0 || port.IndexOf('\0') >= 0))
        {
            problems.Add(new SettingsProblem("Serial:PortName", port.Trim().Length == 0 ? "is empty; write the serial device, e.g. COM3 or /dev/ttyUSB0" : "contains a NUL character"));
        }

        if (s.BaudRate is { } baud && Array.IndexOf(StandardBaudRates, baud) < 0)
        {
            problems.Add(new SettingsProblem("Serial:BaudRate", $"{baud} is not a standard rate ({string.Join(", ", StandardBaudRates)})"));
        }

        if (s.DataBits is { } dataBits && dataBits is not (7 or 8))
        {
            problems.Add(new SettingsProblem("Serial:DataBits", $"{dataBits} is not 7 or 8"));
        }

        if (s.Parity is { } parity && parity is not (SerialParity.None or SerialParity.Even or SerialParity.Odd))
        {
            problems.Add(new SettingsProblem("Serial:Parity", $"{(int)parity} is not None, Even or Odd"));
        }

        if (s.StopBits is { } stopBits && stopBits is not (SerialStopBits.One or SerialStopBits.Two))
        {
            problems.Add(new SettingsProblem("Serial:StopBits", $"{(int)stopBits} is not One or Two"));
        }

        if (s.Handshake is { } handshake && handshake is not (SerialHandshake.None or SerialHandshake.RequestToSend or SerialHandshake.XOnXOff))
        {
            problems.Add(new SettingsProblem("Serial:Handshake", $"{(int)handshake} is not None, RequestToSend or XOnXOff"));
        }

        if (s.RtsEnable == true && s.Handshake == SerialHandshake.RequestToSend)
        {
            problems.Add(new SettingsProblem("Serial:RtsEnable", "cannot be true with Handshake RequestToSend: the driver controls RTS"));
        }

        if (s.PortName is null && settings.Tcp.Host is not null)
        {
            // Behind a serial-device server only the line's speed and format matter here; the rest is the server's.
            const string why = "applies to a local serial port; the serial-device server's own settings control it";
            if (s.Handshake is not null)
            {
                problems.Add(new SettingsProblem("Serial:Handshake", why));
            }

            if (s.DtrEnable is not null)
            {
                problems.Add(new SettingsProblem("Serial:DtrEnable", why));
            }

            if (s.RtsEnable is not null)
            {
                problems.Add(new SettingsProblem("Serial:RtsEnable", why));
            }
        }
    }

    private static void CheckTcp(HostLinkTcpSettings t, List<SettingsProblem> problems)
    {
        bool used = t.Host is not null || t.Port is not null || t.ConnectTimeout is not null;
        if (!used || problems.Any(p => p.IsAtOrBelow("Tcp")))
        {
            return;
        }

        if (t.Host is null || t.Host.Trim().Length == 0)
        {
            problems.Add(new SettingsProblem("Tcp:Host", t.Host is null ? "is missing; write the serial-device server's host name or address" : "is empty; write the serial-device server's host name or address"));
        }

        if (t.Port is not { } port)
        {
            problems.Add(new SettingsProblem("Tcp:Port", "is missing; write the serial-device server's TCP port (1-65535)"));
        }
        else if (port is < 1 or > 65535)
        {
            problems.Add(new SettingsProblem("Tcp:Port", $"{port} is not a TCP port (1-65535)"));
        }

        if (t.ConnectTimeout is { } timeout && (timeout <= TimeSpan.Zero || timeout > LongestConnectTimeout))
        {
            problems.Add(new SettingsProblem("Tcp:ConnectTimeout", $"{Show(timeout)} is not more than 0 and at most 5 minutes"));
        }
    }

    private static void CheckClient(HostLinkClientSettings s, List<SettingsProblem> problems)
    {
        if (s.UnitNumber is { } unit && unit is < 0 or > 31)
        {
            problems.Add(new SettingsProblem("UnitNumber", $"{unit} is not a unit number (0-31)"));
        }

        if (s.Protocol is { } protocol && protocol is not (HostLinkCommandSet.CMode or HostLinkCommandSet.Fins))
        {
            problems.Add(new SettingsProblem("Protocol", $"{(int)protocol} is not CMode or Fins"));
        }

        if (s.TurnaroundAllowance is { } turnaround && (turnaround <= TimeSpan.Zero || turnaround > LongestTurnaround))
        {
            problems.Add(new SettingsProblem("TurnaroundAllowance", $"{Show(turnaround)} is not more than 0 and at most 1 minute"));
        }

        if (s.ReadRetries is { } readRetries && readRetries is < 0 or > 10)
        {
            problems.Add(new SettingsProblem("ReadRetries", $"{readRetries} is not 0-10"));
        }

        if (s.WriteRetries is { } writeRetries && writeRetries is < 0 or > 10)
        {
            problems.Add(new SettingsProblem("WriteRetries", $"{writeRetries} is not 0-10"));
        }

        if (s.WordOrder is { } order && order is not (WordOrder.LowWordFirst or WordOrder.HighWordFirst))
        {
            problems.Add(new SettingsProblem("WordOrder", $"{(int)order} is not LowWordFirst or HighWordFirst"));
        }

        if (s.FinsResponseWait is { } wait && wait is < 0 or > 15)
        {
            problems.Add(new SettingsProblem("FinsResponseWait", $"{wait} is not 0-15 (units of 10 ms)"));
        }

        if (s.Model is { } model && !string.Equals(model, "auto", StringComparison.OrdinalIgnoreCase) && !PlcModelProfile.TryParse(model, out _))
        {
            problems.Add(new SettingsProblem("Model", $"'{model}' is not a known PLC model; use one of {string.Join(", ", PlcModelProfile.All.Select(p => p.Name))}, or auto to ask the PLC (MM)"));
        }
    }

    private static string Show(TimeSpan value) => value.ToString("c", CultureInfo.InvariantCulture);
}
