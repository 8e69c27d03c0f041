using System.CommandLine;
using OmronHostLink.Transports;

namespace OmronHostLink.Cli;

/// <summary>The options every command that talks to a PLC shares, and the client they describe.</summary>
internal sealed class ConnectionOptions
{
    public ConnectionOptions(bool includeUnit = true, int? defaultTimeoutMs = null, int? defaultRetries = null)
    {
        IncludeUnit = includeUnit;
        DefaultTimeoutMs = defaultTimeoutMs;
        DefaultRetries = defaultRetries;
        Port = new Option<string?>("--port") { Description = "Serial port: COM3, /dev/ttyUSB0, or any device path (a pty).", HelpName = "name" };
        Baud = OptionValues.BaudRate("--baud", "Baud rate.", 9600);
        DataBits = OptionValues.IntegerChoice("--data-bits", "Data bits: 7 or 8.", 7, 7, 8);
        Parity = OptionValues.Choice("--parity", "Parity.", "even", "none", "even", "odd");
        StopBits = OptionValues.IntegerChoice("--stop-bits", "Stop bits: 1 or 2.", 2, 1, 2);
        Tcp = new Option<string?>("--tcp") { Description = "A serial device server or the simulator, as host:port.", HelpName = "host:port" };
        Unit = OptionValues.Integer("--unit", "The PLC's unit number, 0-31.", 0, 0, 31, "0-31");
        Timeout = Durations.Option("--timeout", "Time the PLC may take to start answering a frame (the wire time is added); default " + Durations.Format(TimeSpan.FromMilliseconds(defaultTimeoutMs ?? 300)) + ".", null, TimeSpan.FromMilliseconds(1), TimeSpan.FromMinutes(1));
        Retries = OptionValues.OptionalInteger("--retries", "Times a read is repeated after a timeout or damaged frame, 0-10 (writes are never repeated).", 0, 10, "n");
        Fins = new Option<bool>("--fins") { Description = "Use FINS over Host Link (FA) where C-mode would otherwise be used: reads, writes, bit writes, status and mode." };
        Model = new Option<string?>("--model") { Description = "The PLC model addresses and commands are checked against before anything is sent (CPM1A, CP1E-E, C200HS, CS1, ...: see 'hostlink model --list'), or auto to ask the PLC (MM).", HelpName = "name" };
    }

    public bool IncludeUnit { get; }

    public int? DefaultTimeoutMs { get; }

    public int? DefaultRetries { get; }

    public Option<string?> Port { get; }

    public Option<int> Baud { get; }

    public Option<int> DataBits { get; }

    public Option<string> Parity { get; }

    public Option<int> StopBits { get; }

    public Option<string?> Tcp { get; }

    public Option<int> Unit { get; }

    public Option<TimeSpan?> Timeout { get; }

    public Option<int?> Retries { get; }

    public Option<bool> Fins { get; }

    public Option<string?> Model { get; }

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
    }

    /// <summary>The unit number asked for, checked.</summary>
    public int GetUnit(ParseResult parse)
    {
        int unit = parse.GetValue(Unit);
        if (unit is < 0 or > 31)
        {
            throw new UsageException($"--unit must be 0-31; {unit} is not.");
        }

        return unit;
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

        int unit = unitOverride >= 0 ? unitOverride : IncludeUnit ? GetUnit(parse) : 0;
        TimeSpan timeout = parse.GetValue(Timeout) ?? TimeSpan.FromMilliseconds(DefaultTimeoutMs ?? 300);
        int retries = parse.GetValue(Retries) ?? DefaultRetries ?? 2;
        if (retries is < 0 or > 10)
        {
            throw new UsageException($"--retries must be 0-10; {retries} is not.");
        }

        var options = new HostLinkClientOptions
        {
            UnitNumber = unit,
            TurnaroundAllowance = timeout,
            ReadRetries = retries,
            WriteRetries = 0,
            WordOrder = WordOrder,
            CommandSet = parse.GetValue(Fins) ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode,
            Model = parse.GetValue(Model),
        };

        if (options.Model is { } model && !string.Equals(model, "auto", StringComparison.OrdinalIgnoreCase) && !PlcModelProfile.TryParse(model, out _))
        {
            throw new UsageException($"--model '{model}' is not a known PLC model; use one of {PlcModelProfile.KnownNames()}, or auto to ask the PLC (MM).");
        }

        configure?.Invoke(options);
        HostLinkClient client;
        if (tcp is not null && !string.IsNullOrWhiteSpace(tcp))
        {
            (string host, int tcpPort) = ParseEndpoint(tcp, "--tcp");
            SerialLineSettings line = SerialSettings(parse, "tcp");
            options.LineTiming = new LineTiming(line.BaudRate, line.BitsPerCharacter);
            client = HostLinkClient.ForTcp(host, tcpPort, options, TimeSpan.FromSeconds(5));
        }
        else
        {
            SerialLineSettings settings = SerialSettings(parse, port!);
            client = HostLinkClient.ForSerialPort(settings, options);
        }

        if (output.Verbose)
        {
            client.FrameObserver = output.FrameTrace();
        }

        return client;
    }

    /// <summary>The serial line settings from the options.</summary>
    public SerialLineSettings SerialSettings(ParseResult parse, string portName)
    {
        var settings = new SerialLineSettings
        {
            PortName = portName,
            BaudRate = parse.GetValue(Baud),
            DataBits = parse.GetValue(DataBits),
            Parity = parse.GetValue(Parity) switch
            {
                "none" => SerialParity.None,
                "odd" => SerialParity.Odd,
                _ => SerialParity.Even,
            },
            StopBits = parse.GetValue(StopBits) == 1 ? SerialStopBits.One : SerialStopBits.Two,
        };
        try
        {
            settings.Validate();
        }
        catch (ArgumentException e)
        {
            throw new UsageException(OptionValues.SerialMessage(e), e);
        }

        return settings;
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
}
