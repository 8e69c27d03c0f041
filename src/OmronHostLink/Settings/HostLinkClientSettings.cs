using ClientSetting = OmronHostLink.Declare<OmronHostLink.HostLinkClientSettings, OmronHostLink.HostLinkClientOptions>;
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
    /// <summary>The UnitNumber setting.</summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions, int?> UnitNumberSetting =
        ClientSetting.Value(nameof(UnitNumber), s => s.UnitNumber, (s, v) => s.UnitNumber = v, v => v.Integer(), SettingRules.UnitNumber, o => o.UnitNumber, (o, v) => o.UnitNumber = v);

    /// <summary>The CommandSet setting.</summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions, HostLinkCommandSet?> CommandSetSetting =
        ClientSetting.Value(nameof(CommandSet), s => s.CommandSet, (s, v) => s.CommandSet = v, v => v.Choice<HostLinkCommandSet>(), SettingRules.Defined, o => o.CommandSet, (o, v) => o.CommandSet = v).Renamed("Protocol");

    /// <summary>The TurnaroundAllowance setting.</summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions, TimeSpan?> TurnaroundAllowanceSetting =
        ClientSetting.Value(nameof(TurnaroundAllowance), s => s.TurnaroundAllowance, (s, v) => s.TurnaroundAllowance = v, v => v.Duration(), SettingRules.TurnaroundAllowance, o => o.TurnaroundAllowance, (o, v) => o.TurnaroundAllowance = v);

    /// <summary>The ReadRetries setting.</summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions, int?> ReadRetriesSetting =
        ClientSetting.Value(nameof(ReadRetries), s => s.ReadRetries, (s, v) => s.ReadRetries = v, v => v.Integer(), SettingRules.Retries, o => o.ReadRetries, (o, v) => o.ReadRetries = v);

    /// <summary>The AllowReadModifyWriteBits setting.</summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions, bool?> AllowReadModifyWriteBitsSetting =
        ClientSetting.Value(nameof(AllowReadModifyWriteBits), s => s.AllowReadModifyWriteBits, (s, v) => s.AllowReadModifyWriteBits = v, v => v.Boolean(), null, o => o.AllowReadModifyWriteBits, (o, v) => o.AllowReadModifyWriteBits = v);

    /// <summary>
    /// The client settings, each declared once: key, reader, rule and how it applies to <see cref="HostLinkClientOptions"/>
    /// (whose new instance holds the default). <see cref="Read"/>, <see cref="Validate"/> and <see cref="ToClientOptions"/>
    /// iterate them; the console and <see cref="HostLinkPlc"/> take their defaults from them. A new setting is a line
    /// here, its property below and its option.
    /// </summary>
    internal static readonly Setting<HostLinkClientSettings, HostLinkClientOptions>[] Declared =
    [
        UnitNumberSetting,
        CommandSetSetting,
        TurnaroundAllowanceSetting,
        ReadRetriesSetting,
        ClientSetting.Value(nameof(WriteRetries), s => s.WriteRetries, (s, v) => s.WriteRetries = v, v => v.Integer(), SettingRules.Retries, o => o.WriteRetries, (o, v) => o.WriteRetries = v),
        ClientSetting.Value(nameof(WordOrder), s => s.WordOrder, (s, v) => s.WordOrder = v, v => v.Choice<WordOrder>(), SettingRules.Defined, o => o.WordOrder, (o, v) => o.WordOrder = v),
        ClientSetting.Value(nameof(LocalEcho), s => s.LocalEcho, (s, v) => s.LocalEcho = v, v => v.Boolean(), null, o => o.LocalEcho, (o, v) => o.LocalEcho = v),
        ClientSetting.Value(nameof(VerifyAnswers), s => s.VerifyAnswers, (s, v) => s.VerifyAnswers = v, v => v.Boolean(), null, o => o.VerifyAnswers, (o, v) => o.VerifyAnswers = v),
        ClientSetting.Value(nameof(FinsResponseWait), s => s.FinsResponseWait, (s, v) => s.FinsResponseWait = v, v => v.Integer(), SettingRules.FinsResponseWait, o => o.FinsResponseWait, (o, v) => o.FinsResponseWait = v),
        AllowReadModifyWriteBitsSetting,
        ClientSetting.Value(nameof(UseCompoundRead), s => s.UseCompoundRead, (s, v) => s.UseCompoundRead = v, v => v.Choice(("true", CompoundReadMode.On), ("false", CompoundReadMode.Off)), SettingRules.Defined, o => o.UseCompoundRead, (o, v) => o.UseCompoundRead = v),
        ClientSetting.Reference(nameof(Model), s => s.Model, (s, v) => s.Model = v, v => v.Text(), PlcModelProfile.CheckSetting, o => o.Model, (o, v) => o.Model = v),
        ClientSetting.Value(
            nameof(HostLinkCompatibleMode),
            s => s.HostLinkCompatibleMode,
            (s, v) => s.HostLinkCompatibleMode = v,
            v => v.Choice(
                ("A", OmronHostLink.HostLinkCompatibleMode.ModeA),
                ("B", OmronHostLink.HostLinkCompatibleMode.ModeB),
                ("C", OmronHostLink.HostLinkCompatibleMode.ModeC),
                ("D", OmronHostLink.HostLinkCompatibleMode.ModeD)),
            SettingRules.Defined,
            o => o.HostLinkCompatibleMode,
            (o, v) => o.HostLinkCompatibleMode = v),
        ClientSetting.Value(nameof(SendInterval), s => s.SendInterval, (s, v) => s.SendInterval = v, v => v.Duration(), SettingRules.SendInterval, o => o.SendInterval, (o, v) => o.SendInterval = v),
        ClientSetting.Reference(nameof(TraceFile), s => s.TraceFile, (s, v) => s.TraceFile = v, v => v.Text(), SettingRules.TraceFile, o => o.TraceFile, (o, v) => o.TraceFile = v),
        ClientSetting.Reference(nameof(UnitSendIntervals), s => s.UnitSendIntervals, (s, v) => s.UnitSendIntervals = v, v => v.UnitDurations(), SettingRules.UnitSendIntervals, o => o.UnitSendIntervals, (o, v) => o.UnitSendIntervals = new Dictionary<int, TimeSpan>(v)),
    ];

    private static readonly SettingKeys<HostLinkClientSettings> Keys = SettingKeys<HostLinkClientSettings>.Of(
        "a Host Link client setting",
        Declared,
        (nameof(Serial), (v, s) => s.Serial.Read(v)),
        (nameof(Tcp), (v, s) => s.Tcp.Read(v)))
        .WithRenamed("LineBaudRate", "Serial:BaudRate")
        .WithRenamed("ConnectTimeout", "Tcp:ConnectTimeout");

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
    /// A file every frame the client sends and receives is written to, with its time and direction: a pcap for
    /// Wireshark (see <see cref="HostLinkClientOptions.TraceFile"/>), or JSON lines for a name ending in <c>.jsonl</c>.
    /// Default none.
    /// </summary>
    public string? TraceFile { get; set; }

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

    /// <summary>
    /// Whether planned reads use QQ, the compound read: Auto (default: where the unit's model, configured or asked with
    /// MM once, has it), On (unless the model is known to lack it) or Off; true and false are taken for On and Off. See
    /// <see cref="HostLinkClientOptions.UseCompoundRead"/>.
    /// </summary>
    public CompoundReadMode? UseCompoundRead { get; set; }

    /// <summary>
    /// Longer gaps than <see cref="SendInterval"/> before commands to particular units (unit number to gap, each 0 to
    /// 10 s; in configuration a section such as <c>"UnitSendIntervals": { "3": "200ms" }</c>). See
    /// <see cref="HostLinkClientOptions.UnitSendIntervals"/>. Default none.
    /// </summary>
    [System.Diagnostics.CodeAnalysis.SuppressMessage("Usage", "CA2227:Collection properties should be read only", Justification = "Settings are bound and replaced as a whole, as the options' dictionary is.")]
    public IDictionary<int, TimeSpan>? UnitSendIntervals { get; set; }

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

        foreach (Setting<HostLinkClientSettings, HostLinkClientOptions> setting in Declared)
        {
            if (setting.Check(this) is { } problem)
            {
                problems.Add(new HostLinkSettingsProblem(setting.Key, problem));
            }
        }

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
        foreach (Setting<HostLinkClientSettings, HostLinkClientOptions> setting in Declared)
        {
            setting.Apply(this, options);
        }

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
