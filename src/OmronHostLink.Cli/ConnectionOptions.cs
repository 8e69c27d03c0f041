using System.CommandLine;
using System.CommandLine.Parsing;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli;

/// <summary>
/// The options every command that talks to a PLC shares. They build the library's one client settings type
/// (<see cref="HostLinkClientSettings"/>), whose validation is the only check of their ranges: a problem is a parse
/// error naming the option, so nothing is sent.
/// </summary>
internal sealed class ConnectionOptions
{
    /// <summary>The option that sets each settings key, for the settings' problems in the console's terms.</summary>
    private static readonly Dictionary<string, string> OptionOfKey = new(StringComparer.OrdinalIgnoreCase)
    {
        ["Serial:PortName"] = "--port",
        ["Serial:BaudRate"] = "--baud",
        ["Serial:DataBits"] = "--data-bits",
        ["Serial:Parity"] = "--parity",
        ["Serial:StopBits"] = "--stop-bits",
        ["Tcp:Host"] = "--tcp",
        ["Tcp:Port"] = "--tcp",
        ["UnitNumber"] = "--unit",
        ["TurnaroundAllowance"] = "--timeout",
        ["ReadRetries"] = "--retries",
        ["Model"] = "--model",
        ["HostLinkCompatibleMode"] = "--compatible-mode",
        ["LocalEcho"] = "--local-echo",
    };

    public ConnectionOptions(bool includeUnit = true, TimeSpan? defaultTimeout = null, int? defaultRetries = null)
    {
        IncludeUnit = includeUnit;
        DefaultTimeout = defaultTimeout;
        DefaultRetries = defaultRetries;
        var line = new SerialLineSettings();
        TimeSpan timeout = defaultTimeout ?? new HostLinkClientOptions().TurnaroundAllowance;
        Port = new Option<string?>("--port") { Description = "Serial port: COM3, /dev/ttyUSB0, or any device path (a pty).", HelpName = "name" };
        Baud = OptionValues.OptionalInteger("--baud", $"Baud rate (default {line.BaudRate}).", int.MinValue, int.MaxValue, "n");
        DataBits = OptionValues.OptionalInteger("--data-bits", $"Data bits: {SettingRules.MinDataBits} or {SettingRules.MaxDataBits} (default {line.DataBits}).", int.MinValue, int.MaxValue, $"{SettingRules.MinDataBits}|{SettingRules.MaxDataBits}");
        string[] parities = Enum.GetNames(typeof(SerialParity)).Select(n => n.ToLowerInvariant()).ToArray();
        Parity = OptionValues.OptionalChoice("--parity", $"Parity (default {line.Parity.ToString().ToLowerInvariant()}).", string.Join('|', parities), parities);
        StopBits = OptionValues.OptionalInteger("--stop-bits", $"Stop bits: 1 or 2 (default {(int)line.StopBits}).", int.MinValue, int.MaxValue, "1|2");
        Tcp = new Option<string?>("--tcp") { Description = "A serial device server or the simulator, as host:port.", HelpName = "host:port" };
        Unit = OptionValues.Integer("--unit", $"The PLC's unit number, 0-{SettingRules.MaxUnitNumber}.", 0, int.MinValue, int.MaxValue, "n");
        Timeout = Durations.Option("--timeout", "Time the PLC may take to start answering a frame (the wire time is added); default " + Durations.Format(timeout) + ".", null, TimeSpan.MinValue, TimeSpan.MaxValue);
        Retries = OptionValues.OptionalInteger("--retries", $"Times a read is repeated after a timeout or damaged frame, 0-{SettingRules.MaxRetries} (writes are never repeated).", int.MinValue, int.MaxValue, "n");
        Fins = new Option<bool>("--fins") { Description = "Use FINS over Host Link (FA) where C-mode would otherwise be used: reads, writes, bit writes, status and mode." };
        CompatibleMode = OptionValues.OptionalChoice("--compatible-mode", "The Host Link-compatible device mode the PLC's Serial Communications Unit is set to (A: CS/CJ/C, B: CVM1/CV, C: C200H, D: C500/C120): each answer frame is checked to be framed as that mode frames it. Default: any framing.", "a|b|c|d", "a", "b", "c", "d");
        Trace = new Option<string?>("--trace") { Description = "Write every frame sent and received, with its time and direction, to this file: a pcap for Wireshark (tools/wireshark/omron-hostlink.lua), or JSON lines for a name ending in .jsonl.", HelpName = "file" };
        LocalEcho = new Option<bool>("--local-echo") { Description = "The line echoes what is sent (a 2-wire RS-485 adapter without echo suppression; 'hostlink detect' tells): read our own frames back before each answer." };
        Model = new Option<string?>("--model") { Description = "The PLC model addresses and commands are checked against before anything is sent (CPM1A, CP1E-E, C200HS, CS1, ...: see 'hostlink model --list'), or auto to ask the PLC (MM).", HelpName = "name" };
    }

    public bool IncludeUnit { get; }

    public TimeSpan? DefaultTimeout { get; }

    public int? DefaultRetries { get; }

    public Option<string?> Port { get; }

    public Option<int?> Baud { get; }

    public Option<int?> DataBits { get; }

    public Option<string?> Parity { get; }

    public Option<int?> StopBits { get; }

    public Option<string?> Tcp { get; }

    public Option<int> Unit { get; }

    public Option<TimeSpan?> Timeout { get; }

    public Option<int?> Retries { get; }

    public Option<bool> Fins { get; }

    public Option<string?> Model { get; }

    public Option<string?> CompatibleMode { get; }

    public Option<bool> LocalEcho { get; }

    public Option<string?> Trace { get; }

    /// <summary>How 32- and 64-bit values lie in two or four words: Omron's own layout, low word first.</summary>
    public WordOrder WordOrder => WordOrder.LowWordFirst;

    public void AddTo(Command command)
    {
        command.Add(Port);
        command.Add(Baud);
        command.Add(DataBits);
        command.Add(Parity);
        command.Add(StopBits);
        command.Add(Tcp);
        if (IncludeUnit)
        {
            command.Add(Unit);
        }

        command.Add(Timeout);
        command.Add(Retries);
        command.Add(Fins);
        command.Add(Model);
        command.Add(CompatibleMode);
        command.Add(LocalEcho);
        command.Add(Trace);
        command.Validators.Add(Validate);
    }

    /// <summary>The unit number asked for (checked with the other settings when the command line is parsed).</summary>
    public int GetUnit(ParseResult parse) => parse.GetValue(Unit);

    /// <summary>
    /// The client settings the options describe. Which link (<c>--port</c> or <c>--tcp</c>) is checked by
    /// <see cref="CreateClient"/>, in the console's words; every other rule by <see cref="HostLinkClientSettings.Validate"/>.
    /// </summary>
    public HostLinkClientSettings ToSettings(SymbolResult options, int unitOverride = -1)
    {
        var settings = new HostLinkClientSettings
        {
            UnitNumber = unitOverride >= 0 ? unitOverride : IncludeUnit ? options.GetValue(Unit) : 0,
            TurnaroundAllowance = options.GetValue(Timeout) ?? DefaultTimeout,
            ReadRetries = options.GetValue(Retries) ?? DefaultRetries,
            WriteRetries = 0,
            WordOrder = WordOrder,
            CommandSet = options.GetValue(Fins) ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode,
            Model = options.GetValue(Model),
            LocalEcho = options.GetValue(LocalEcho) ? true : null,
            HostLinkCompatibleMode = options.GetValue(CompatibleMode) switch
            {
                "a" => HostLinkCompatibleMode.ModeA,
                "b" => HostLinkCompatibleMode.ModeB,
                "c" => HostLinkCompatibleMode.ModeC,
                "d" => HostLinkCompatibleMode.ModeD,
                _ => null,
            },
        };
        settings.Serial.BaudRate = options.GetValue(Baud);
        settings.Serial.DataBits = options.GetValue(DataBits);
        settings.Serial.Parity = Enum.TryParse(options.GetValue(Parity), ignoreCase: true, out SerialParity parity) ? parity : null;
        settings.Serial.StopBits = (SerialStopBits?)options.GetValue(StopBits);
        string? tcp = options.GetValue(Tcp);
        if (!string.IsNullOrWhiteSpace(tcp))
        {
            (settings.Tcp.Host, int port) = ParseEndpoint(tcp!, "--tcp");
            settings.Tcp.Port = port;
            settings.Tcp.ConnectTimeout = TimeSpan.FromSeconds(5);
        }
        else
        {
            settings.Serial.PortName = options.GetValue(Port);
        }

        return settings;
    }

    /// <summary>
    /// Checks the options and creates the client (nothing is opened or sent until the first exchange).
    /// </summary>
    /// <exception cref="UsageException">The options are contradictory or out of range.</exception>
    public HostLinkClient CreateClient(ParseResult parse, OutputWriter output, int unitOverride = -1, Action<HostLinkClientOptions>? configure = null)
    {
        string? port = parse.GetValue(Port);
        string? tcp = parse.GetValue(Tcp);
        if (string.IsNullOrWhiteSpace(port) == string.IsNullOrWhiteSpace(tcp))
        {
            throw new UsageException(port is null && tcp is null
                ? "Say where the PLC is: give --port <name> for a serial port or --tcp <host:port> for a device server or the simulator."
                : "Give either --port or --tcp, not both.");
        }

        HostLinkClientSettings settings = ToSettings(parse.CommandResult, unitOverride);
        if (Problems(settings).FirstOrDefault() is { } problem)
        {
            throw new UsageException(problem);
        }

        string? trace = parse.GetValue(Trace);
        HostLinkClient client;
        try
        {
            client = settings.CreateClient(trace is null ? configure : o =>
            {
                configure?.Invoke(o);
                o.TraceFile = trace;
            });
        }
        catch (ArgumentException e) when (e.ParamName == nameof(HostLinkClientOptions.TraceFile))
        {
            throw new UsageException($"--trace: cannot create '{trace}': {e.InnerException?.Message ?? e.Message}", e);
        }

        if (output.Verbose)
        {
            client.FrameObserver = output.FrameTrace();
        }

        return client;
    }

    /// <summary>Parses host:port.</summary>
    public static (string Host, int Port) ParseEndpoint(string text, string option)
    {
        try
        {
            return TcpTransport.ParseEndpoint(text);
        }
        catch (FormatException e)
        {
            throw new UsageException($"{option}: {e.Message}", e);
        }
    }

    /// <summary>The settings' problems in the console's words: <c>--baud: 12345 is not a standard rate (…).</c></summary>
    private static IEnumerable<string> Problems(HostLinkClientSettings settings)
        => settings.Validate()
            .Where(p => OptionOfKey.ContainsKey(p.Key))
            .Select(p => $"{OptionOfKey[p.Key]}: {p.Message}.");

    private void Validate(CommandResult result)
    {
        try
        {
            foreach (string problem in Problems(ToSettings(result)))
            {
                result.AddError(problem);
            }
        }
        catch (UsageException e)
        {
            result.AddError(e.Message);
        }
        catch (InvalidOperationException)
        {
            // An option's value could not be read at all: its own parse error says so.
        }
    }
}
