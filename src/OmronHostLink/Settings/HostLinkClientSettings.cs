using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// Everything a Host Link client takes, in one place: the link (a local serial port, or a TCP serial-device server and
/// the serial line behind it), the unit, the command set, the turnaround allowance, retries, word order and local echo.
/// The DI package binds it from configuration, the worker and the gateway nest it per link, the console builds it from
/// its options; <see cref="Validate"/> is the one check, and <see cref="CreateClient"/> makes the client.
/// Every setting left unset (null) takes the library's default.
/// </summary>
/// <example>
/// <code>
/// var settings = new HostLinkClientSettings { UnitNumber = 3, CommandSet = HostLinkCommandSet.Fins };
/// settings.Serial.PortName = "/dev/ttyUSB0";
/// await using HostLinkClient plc = settings.CreateClient();
/// </code>
/// </example>
public sealed class HostLinkClientSettings
{
    private static readonly SettingKeys<HostLinkClientSettings> Keys = new("a Host Link client setting")
    {
        { nameof(Serial), (v, s) => s.Serial.Read(v) },
        { nameof(Tcp), (v, s) => s.Tcp.Read(v) },
        { nameof(UnitNumber), (v, s) => s.UnitNumber = v.Integer() ?? s.UnitNumber },
        { nameof(CommandSet), (v, s) => s.CommandSet = v.Choice<HostLinkCommandSet>() ?? s.CommandSet },
        { nameof(TurnaroundAllowance), (v, s) => s.TurnaroundAllowance = v.Duration() ?? s.TurnaroundAllowance },
        { nameof(ReadRetries), (v, s) => s.ReadRetries = v.Integer() ?? s.ReadRetries },
        { nameof(WriteRetries), (v, s) => s.WriteRetries = v.Integer() ?? s.WriteRetries },
        { nameof(WordOrder), (v, s) => s.WordOrder = v.Choice<WordOrder>() ?? s.WordOrder },
        { nameof(LocalEcho), (v, s) => s.LocalEcho = v.Boolean() ?? s.LocalEcho },
        { nameof(VerifyAnswers), (v, s) => s.VerifyAnswers = v.Boolean() ?? s.VerifyAnswers },
        { nameof(FinsResponseWait), (v, s) => s.FinsResponseWait = v.Integer() ?? s.FinsResponseWait },
        { nameof(AllowReadModifyWriteBits), (v, s) => s.AllowReadModifyWriteBits = v.Boolean() ?? s.AllowReadModifyWriteBits },
        { nameof(Model), (v, s) => s.Model = v.Text() ?? s.Model },
        {
            nameof(HostLinkCompatibleMode),
            (v, s) => s.HostLinkCompatibleMode = v.Choice(
                ("A", OmronHostLink.HostLinkCompatibleMode.ModeA),
                ("B", OmronHostLink.HostLinkCompatibleMode.ModeB),
                ("C", OmronHostLink.HostLinkCompatibleMode.ModeC),
                ("D", OmronHostLink.HostLinkCompatibleMode.ModeD)) ?? s.HostLinkCompatibleMode
        },
        { nameof(SendInterval), (v, s) => s.SendInterval = v.Duration() ?? s.SendInterval },
    };

    private readonly List<HostLinkSettingsProblem> _readProblems = new();

    /// <summary>
    /// The serial line: for a local port, the port and its settings; behind a serial-device server, the line's speed
    /// and character format, from which frame deadlines are derived.
    /// </summary>
    public HostLinkSerialSettings Serial { get; set; } = new();

    /// <summary>A serial-device server (or the simulator) reached over TCP instead of a local port.</summary>
    public HostLinkTcpSettings Tcp { get; set; } = new();

    /// <summary>The unit number the client addresses, 0-31. Default 0.</summary>
    public int? UnitNumber { get; set; }

    /// <summary>The command set reads and writes use: <see cref="HostLinkCommandSet.CMode"/> (default) or <see cref="HostLinkCommandSet.Fins"/>.</summary>
    public HostLinkCommandSet? CommandSet { get; set; }

    /// <summary>
    /// How long the PLC (and a gateway between) may take to start answering a frame, on top of the frame's wire time.
    /// More than zero, at most 1 minute. Default 300 ms.
    /// </summary>
    public TimeSpan? TurnaroundAllowance { get; set; }

    /// <summary>How many times a read is repeated after a timeout or a damaged frame, 0-10. Default 2.</summary>
    public int? ReadRetries { get; set; }

    /// <summary>
    /// How many times a write is repeated after a timeout or a damaged frame, 0-10. Default 0: a write whose answer was
    /// lost may have been carried out.
    /// </summary>
    public int? WriteRetries { get; set; }

    /// <summary>How 32-bit values lie in two words. Default <see cref="OmronHostLink.WordOrder.LowWordFirst"/> (Omron's layout).</summary>
    public WordOrder? WordOrder { get; set; }

    /// <summary>The line echoes what we send (2-wire RS-485 without echo suppression). Default false.</summary>
    public bool? LocalEcho { get; set; }

    /// <summary>
    /// Send a TS check behind every C-mode answer and take the answer only when the check comes back next, for lines
    /// known to deliver answers out of turn (see <see cref="HostLinkClientOptions.VerifyAnswers"/>). Default false.
    /// </summary>
    public bool? VerifyAnswers { get; set; }

    /// <summary>The FINS response wait time sent in every FINS frame, 0-15 in units of 10 ms. Default 0.</summary>
    public int? FinsResponseWait { get; set; }

    /// <summary>
    /// Allow bit writes by reading the word, changing the bit and writing the word back. Default false: a change the PLC
    /// program makes to the word between the read and the write is lost.
    /// </summary>
    public bool? AllowReadModifyWriteBits { get; set; }

    /// <summary>
    /// The PLC model addresses and commands are checked against before anything is sent (see
    /// <see cref="HostLinkClientOptions.Model"/>): CPM1A, CP1E-E, C200HS, CS1, ..., or auto to ask the PLC (MM).
    /// Default none: the CS/CJ sizes only.
    /// </summary>
    public string? Model { get; set; }

    /// <summary>
    /// The Host Link-compatible device mode of the Serial Communications Unit the client talks to, when it is set to one
    /// and its answers should be checked against it (see <see cref="HostLinkClientOptions.HostLinkCompatibleMode"/>):
    /// ModeA to ModeD, or A to D. Default none: any framing is accepted.
    /// </summary>
    public HostLinkCompatibleMode? HostLinkCompatibleMode { get; set; }

    /// <summary>
    /// The least time between the end of one exchange and the next command on the line, for PLCs and converters that
    /// drop a command sent right after an answer; 0 to 10 s. Default 0 (none). See <see cref="HostLinkClientOptions.SendInterval"/>.
    /// </summary>
    public TimeSpan? SendInterval { get; set; }

    /// <summary>The kinds of link a client can use; exactly one is chosen.</summary>
    internal IEnumerable<HostLinkEndpointSettings> Endpoints => [Serial, Tcp];

    /// <summary>
    /// Reads settings from <c>key = value</c> pairs as configuration flattens a client's section: keys relative to the
    /// section, separated by <c>:</c> (<c>Serial:BaudRate</c>), in any case; durations as <see cref="Duration"/> reads
    /// them. A key or value that cannot be used is not thrown but kept, and reported by <see cref="Validate"/>.
    /// </summary>
    /// <param name="values">The pairs, such as <c>IConfiguration.AsEnumerable(makePathsRelative: true)</c>.</param>
    public void Read(IEnumerable<KeyValuePair<string, string?>> values)
    {
        Guard.NotNull(values);
        Keys.Read(SettingNode.From(values), "", this, _readProblems, Suggest);
    }

    /// <summary>
    /// Every problem of these settings at once, each with its key path (<c>Serial:BaudRate</c>): values
    /// <see cref="Read"/> could not use, values out of range, and a link that is missing or chosen twice.
    /// </summary>
    /// <returns>The problems; empty when a client can be created.</returns>
    public IReadOnlyList<HostLinkSettingsProblem> Validate()
    {
        var problems = new List<HostLinkSettingsProblem>(_readProblems);
        if (Serial is null || Tcp is null)
        {
            problems.Add(new HostLinkSettingsProblem(Serial is null ? nameof(Serial) : nameof(Tcp), "is missing"));
            return problems;
        }

        CheckLink(problems);
        foreach (HostLinkEndpointSettings endpoint in Endpoints)
        {
            endpoint.Check(this, problems);
        }

        void Add(string key, string? problem)
        {
            if (problem is not null)
            {
                problems.Add(new HostLinkSettingsProblem(key, problem));
            }
        }

        Add(nameof(UnitNumber), UnitNumber is { } unit ? SettingRules.UnitNumber(unit) : null);
        Add(nameof(CommandSet), CommandSet is { } commandSet ? SettingRules.CommandSet(commandSet) : null);
        Add(nameof(TurnaroundAllowance), TurnaroundAllowance is { } turnaround ? SettingRules.TurnaroundAllowance(turnaround) : null);
        Add(nameof(ReadRetries), ReadRetries is { } readRetries ? SettingRules.Retries(readRetries) : null);
        Add(nameof(WriteRetries), WriteRetries is { } writeRetries ? SettingRules.Retries(writeRetries) : null);
        Add(nameof(WordOrder), WordOrder is { } order ? SettingRules.WordOrder(order) : null);
        Add(nameof(FinsResponseWait), FinsResponseWait is { } wait ? SettingRules.FinsResponseWait(wait) : null);
        Add(nameof(Model), Model is { } model ? SettingRules.Model(model) : null);
        Add(nameof(HostLinkCompatibleMode), HostLinkCompatibleMode is { } compatibleMode ? SettingRules.CompatibleMode(compatibleMode) : null);
        Add(nameof(SendInterval), SendInterval is { } gap ? SettingRules.SendInterval(gap) : null);
        return problems;
    }

    /// <summary>
    /// The client's options from these settings: unset values keep <see cref="HostLinkClientOptions"/>'s defaults, and
    /// the serial line's speed and format set <see cref="HostLinkClientOptions.LineTiming"/>.
    /// </summary>
    /// <returns>New options; add a logger factory, meter factory or link name before creating the client.</returns>
    public HostLinkClientOptions ToClientOptions()
    {
        var options = new HostLinkClientOptions();
        options.UnitNumber = UnitNumber ?? options.UnitNumber;
        options.CommandSet = CommandSet ?? options.CommandSet;
        options.TurnaroundAllowance = TurnaroundAllowance ?? options.TurnaroundAllowance;
        options.ReadRetries = ReadRetries ?? options.ReadRetries;
        options.WriteRetries = WriteRetries ?? options.WriteRetries;
        options.WordOrder = WordOrder ?? options.WordOrder;
        options.LocalEcho = LocalEcho ?? options.LocalEcho;
        options.VerifyAnswers = VerifyAnswers ?? options.VerifyAnswers;
        options.FinsResponseWait = FinsResponseWait ?? options.FinsResponseWait;
        options.AllowReadModifyWriteBits = AllowReadModifyWriteBits ?? options.AllowReadModifyWriteBits;
        options.Model = Model ?? options.Model;
        options.HostLinkCompatibleMode = HostLinkCompatibleMode ?? options.HostLinkCompatibleMode;
        options.SendInterval = SendInterval ?? options.SendInterval;

        // Over TCP the transport cannot know the line's speed: the deadlines come from these settings. A local port
        // gives its own timing from the same values.
        SerialLineSettings line = Serial.ToLineSettings();
        options.LineTiming = new LineTiming(line.BaudRate, line.BitsPerCharacter);
        return options;
    }

    /// <summary>Creates the client these settings describe; nothing opens until the first exchange.</summary>
    /// <param name="configure">Adds what settings do not hold (a logger factory, a meter factory, a link name), or null.</param>
    /// <returns>The client.</returns>
    /// <exception cref="ArgumentException">The settings are not valid; the message lists every problem by its key.</exception>
    public HostLinkClient CreateClient(Action<HostLinkClientOptions>? configure = null)
    {
        IReadOnlyList<HostLinkSettingsProblem> problems = Validate();
        if (problems.Count > 0)
        {
            throw new ArgumentException("The Host Link client settings are not valid: " + string.Join("; ", problems) + ".");
        }

        HostLinkClientOptions options = ToClientOptions();
        configure?.Invoke(options);
        return HostLinkClient.Create(Endpoints.First(e => e.IsChosen).CreateTransport(this), options);
    }

    private void CheckLink(List<HostLinkSettingsProblem> problems)
    {
        // A key that is written but could not be read still says which link was meant.
        HostLinkEndpointSettings[] endpoints = Endpoints.ToArray();
        HostLinkEndpointSettings[] chosen = endpoints.Where(e => e.IsChosen || problems.Any(p => p.IsAtOrBelow(e.ChoiceKey))).ToArray();
        string either = "either " + string.Join(" or ", endpoints.Select(e => e.What));
        if (chosen.Length > 1)
        {
            problems.Add(new HostLinkSettingsProblem(chosen[1].Key, $"cannot be combined with {chosen[0].ChoiceKey}; a client uses {either}"));
        }
        else if (chosen.Length == 0 && !problems.Any(p => p.Key.Length == 0 || endpoints.Any(e => p.Key.Equals(e.Key, StringComparison.OrdinalIgnoreCase))))
        {
            problems.Add(new HostLinkSettingsProblem("", "no link is set; write " + string.Join(" or ", endpoints.Select(e => e.Hint))));
        }
    }

    /// <summary>Where a key people reach for lives instead: <c>BaudRate</c> is <c>Serial:BaudRate</c>.</summary>
    private string? Suggest(string key)
    {
        if (key.Equals("Unit", StringComparison.OrdinalIgnoreCase))
        {
            return nameof(UnitNumber);
        }

        if (key.Equals("Port", StringComparison.OrdinalIgnoreCase))
        {
            return "Serial:PortName or Tcp:Port";
        }

        return Endpoints
            .SelectMany(e => e.KeyNames.Select(k => e.Key + ":" + k))
            .FirstOrDefault(path => path.EndsWith(":" + key, StringComparison.OrdinalIgnoreCase));
    }
}
