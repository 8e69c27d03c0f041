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
        ["TraceFile"] = "--trace",
        ["UseCompoundRead"] = "--compound-read",
    };

    public ConnectionOptions(bool includeUnit = true, TimeSpan? defaultTimeout = null, int? defaultRetries = null, bool plansReads = false)
    {
        IncludeUnit = includeUnit;
        PlansReads = plansReads;
        DefaultTimeout = defaultTimeout;
        DefaultRetries = defaultRetries;
        TimeSpan timeout = defaultTimeout ?? HostLinkClientSettings.TurnaroundAllowanceSetting.Default!.Value;
        Port = new Option<string?>("--port") { Description = "Serial port: COM3, /dev/ttyUSB0, or any device path (a pty).", HelpName = "name" };
        Baud = OptionValues.OptionalInteger("--baud", $"Baud rate (default {HostLinkSerialSettings.BaudRateSetting.Default}).", int.MinValue, int.MaxValue, "n");
        DataBits = OptionValues.OptionalInteger("--data-bits", $"Data bits: {SettingRules.MinDataBits} or {SettingRules.MaxDataBits} (default {HostLinkSerialSettings.DataBitsSetting.Default}).", int.MinValue, int.MaxValue, $"{SettingRules.MinDataBits}|{SettingRules.MaxDataBits}");
        string[] parities = Enum.GetNames(typeof(SerialParity)).Select(n => n.ToLowerInvariant()).ToArray();
        Parity = OptionValues.OptionalChoice("--parity", $"Parity (default {HostLinkSerialSettings.ParitySetting.Default.ToString()!.ToLowerInvariant()}).", string.Join('|', parities), parities);
        StopBits = OptionValues.OptionalInteger("--stop-bits", $"Stop bits: 1 or 2 (default {(int)HostLinkSerialSettings.StopBitsSetting.Default!.Value}).", int.MinValue, int.MaxValue, "1|2");
        Tcp = new Option<string?>("--tcp") { Description = "A serial device server or the simulator, as host:port.", HelpName = "host:port" };
        Unit = OptionValues.Integer("--unit", $"The PLC's unit number, 0-{SettingRules.MaxUnitNumber}.", 0, int.MinValue, int.MaxValue, "n");
        Timeout = Durations.Option("--timeout", "Time the PLC may take to start answering a frame (the wire time is added); default " + Durations.Format(timeout) + ".", null, TimeSpan.MinValue, TimeSpan.MaxValue);
        Retries = OptionValues.OptionalInteger("--retries", $"Times a read is repeated after a timeout or damaged frame, 0-{SettingRules.MaxRetries} (default {DefaultRetries ?? HostLinkClientSettings.ReadRetriesSetting.Default}; writes are never repeated).", int.MinValue, int.MaxValue, "n");
        Fins = new Option<bool>("--fins") { Description = "Use FINS over Host Link (FA) where C-mode would otherwise be used: reads, writes, bit writes, status and mode." };
        CompatibleMode = OptionValues.OptionalChoice("--compatible-mode", "The Host Link-compatible device mode the PLC's Serial Communications Unit is set to (A: CS/CJ/C, B: CVM1/CV, C: C200H, D: C500/C120): each answer frame is checked to be framed as that mode frames it. Default: any framing.", "a|b|c|d", "a", "b", "c", "d");
        Trace = new Option<string?>("--trace") { Description = "Write every frame sent and received, with its time and direction, to this file: a pcap for Wireshark (tools/wireshark/omron-hostlink.lua), or JSON lines for a name ending in .jsonl.", HelpName = "file" };
        LocalEcho = new Option<bool>("--local-echo") { Description = "The line echoes what is sent (a 2-wire RS-485 adapter without echo suppression; 'hostlink detect' tells): read our own frames back before each answer." };
        Set = new Option<string[]>("--set")
        {
            Description = "Any client setting as key=value, as in configuration (repeatable): --set UseCompoundRead=true, --set UnitSendIntervals:3=200ms, --set SendInterval=20ms. See docs/settings.md.",
            HelpName = "key=value",
            AllowMultipleArgumentsPerToken = false,
        };
        CompoundRead = CompoundReadOption();
        Model = new Option<string?>("--model") { Description = "The PLC model addresses and commands are checked against before anything is sent (CPM1A, CP1E-E, C200HS, CS1, ...: see 'hostlink model --list'), or auto to ask the PLC (MM).", HelpName = "name" };
    }

    public bool IncludeUnit { get; }

    /// <summary>Whether the command plans its reads (and so takes <c>--compound-read</c>).</summary>
    public bool PlansReads { get; }

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

    /// <summary><c>--set key=value</c>: every client setting, read as configuration reads it.</summary>
    public Option<string[]> Set { get; }
    public Option<string?> CompoundRead { get; }

    /// <summary><c>--compound-read auto|on|off</c>: whether planned reads use QQ (the client setting UseCompoundRead).</summary>
    public static Option<string?> CompoundReadOption()
        => OptionValues.OptionalChoice("--compound-read", "Whether planned reads use QQ, the compound read: auto (default: where the PLC's model, given with --model or named by MM, has it), on, or off.", "auto|on|off", "auto", "on", "off");

    /// <summary>The mode <paramref name="value"/> (an <see cref="CompoundReadOption"/> value) names; null when not given.</summary>
    public static CompoundReadMode? CompoundReadOf(string? value) => value switch
    {
        "auto" => CompoundReadMode.Auto,
        "on" => CompoundReadMode.On,
        "off" => CompoundReadMode.Off,
        _ => null,
    };

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
        command.Add(Set);
        if (PlansReads)
        {
            command.Add(CompoundRead);
        }

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
            TraceFile = options.GetValue(Trace),
            HostLinkCompatibleMode = options.GetValue(CompatibleMode) switch
            {
                "a" => HostLinkCompatibleMode.ModeA,
                "b" => HostLinkCompatibleMode.ModeB,
                "c" => HostLinkCompatibleMode.ModeC,
                "d" => HostLinkCompatibleMode.ModeD,
                _ => null,
            },
            UseCompoundRead = PlansReads ? CompoundReadOf(options.GetValue(CompoundRead)) : null,
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

        // --set last: any client setting, read as configuration reads it, over what the options above say.
        settings.Read(SetPairs(options.GetValue(Set)));
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

        HostLinkClient client;
        try
        {
            client = settings.CreateClient(configure);
        }
        catch (ArgumentException e) when (e.ParamName == nameof(HostLinkClientOptions.TraceFile))
        {
            throw new UsageException($"--trace: cannot create '{settings.TraceFile}': {e.InnerException?.Message ?? e.Message}", e);
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

    /// <summary>The settings' problems in the console's words: <c>--baud: 12345 is not a standard rate (…).</c>, <c>--set SendInterval: …</c>.</summary>
    private static IEnumerable<string> Problems(HostLinkClientSettings settings)
        => settings.Validate()
            .Where(p => p.Key.Length > 0 && !p.Key.StartsWith("Tcp", StringComparison.OrdinalIgnoreCase) && !p.Key.Equals("Serial:PortName", StringComparison.OrdinalIgnoreCase))
            .Select(p => OptionOfKey.TryGetValue(p.Key, out string? option) ? $"{option}: {p.Message}." : $"--set {p.Key}: {p.Message}.");

    /// <summary>The <c>--set</c> values as configuration's key/value pairs.</summary>
    private static IEnumerable<KeyValuePair<string, string?>> SetPairs(string[]? values)
    {
        foreach (string value in values ?? [])
        {
            int equals = value.IndexOf('=', StringComparison.Ordinal);
            if (equals <= 0)
            {
                throw new UsageException($"--set '{value}': write key=value, for example --set UseCompoundRead=true.");
            }

            yield return new KeyValuePair<string, string?>(value[..equals].Trim(), value[(equals + 1)..]);
        }
    }

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
