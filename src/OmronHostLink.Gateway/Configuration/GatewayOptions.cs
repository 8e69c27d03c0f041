namespace OmronHostLink.Gateway.Configuration;

/// <summary>The <c>HostLink</c> section: the links the worker polls.</summary>
internal sealed class GatewayOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "HostLink";

    /// <summary>The links, keyed by name (the name appears in every log line).</summary>
    public Dictionary<string, LinkOptions> Links { get; set; } = new(StringComparer.OrdinalIgnoreCase);
}

/// <summary>
/// One link: one <see cref="HostLinkClient"/> and its poll groups. Besides <see cref="Enabled"/>, <see cref="Backoff"/>
/// and <see cref="Groups"/>, the link's section holds the client's settings as the library reads them everywhere
/// (<see cref="Client"/>: <c>Serial</c>, <c>Tcp</c>, <c>CommandSet</c>, <c>TurnaroundAllowance</c>, <c>ReadRetries</c>, …).
/// </summary>
internal sealed class LinkOptions
{
    /// <summary>False to keep the link in the file without polling it (for example in one environment only). Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>How often a PLC that stopped answering is tried again.</summary>
    public BackoffOptions Backoff { get; set; } = new();

    /// <summary>When a PLC unit that stays silent is demoted, and for how long.</summary>
    public DemotionOptions Demotion { get; set; } = new();

    /// <summary>The poll groups, keyed by name.</summary>
    public Dictionary<string, PollGroupOptions> Groups { get; set; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>CSV files of tags (Kepware exports or plain files) whose rows become poll groups beside <see cref="Groups"/>.</summary>
    public List<TagFileOptions> TagFiles { get; set; } = new();

    /// <summary>What the tag files could not give, each naming the file and line; reported at start-up.</summary>
    internal List<string> TagFileProblems { get; } = new();

    /// <summary>The link's client, read from the section's other keys by <see cref="HostLinkClientSettings.Read"/>.</summary>
    public HostLinkClientSettings Client { get; } = new();

    /// <summary>The command set the client uses (the address ranges of the groups depend on it).</summary>
    public HostLinkCommandSet CommandSet => Client.CommandSet ?? Defaults.CommandSet;

    /// <summary>How the client's 32-bit values lie in two words.</summary>
    public WordOrder WordOrder => Client.WordOrder ?? Defaults.WordOrder;

    private static HostLinkClientOptions Defaults { get; } = new();
}

/// <summary>Capped exponential backoff: <see cref="Initial"/>, doubling up to <see cref="Max"/>.</summary>
internal sealed class BackoffOptions
{
    /// <summary>The first wait after a PLC stops answering. Default 1 s.</summary>
    public TimeSpan Initial { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>The longest wait between attempts. Default 30 s.</summary>
    public TimeSpan Max { get; set; } = TimeSpan.FromSeconds(30);
}

/// <summary>A block of PLC memory read every <see cref="Interval"/> and logged.</summary>
internal sealed class PollGroupOptions
{
    /// <summary>The PLC's Host Link unit number, 0-31. Default 0.</summary>
    public int Unit { get; set; }

    /// <summary>The first address, CX-Programmer style: <c>D100</c>, <c>CIO10</c>, <c>W20.03</c>, <c>E1_500</c>, <c>T5</c>.</summary>
    public string Address { get; set; } = "";

    /// <summary>How many values of <see cref="Type"/> (characters for <c>string</c>, bits for <c>bit</c>). Default 1.</summary>
    public int Count { get; set; } = 1;

    /// <summary>word | bcd | int16 | uint16 | int32 | uint32 | float | string | bit. Default word.</summary>
    public string Type { get; set; } = "word";

    /// <summary>Time between polls. Default 1 s.</summary>
    public TimeSpan Interval { get; set; } = TimeSpan.FromSeconds(1);

    /// <summary>EveryPoll (default) or OnChange (only values that differ from the last ones logged).</summary>
    public string Log { get; set; } = nameof(PollLogMode.EveryPoll);

    /// <summary>Allow writes to this group from MQTT and Sparkplug B (with their <c>Writes:Enabled</c>). Default false.</summary>
    public bool Writable { get; set; }

    /// <summary>
    /// For a group made from a row of a tag file: the file and line (<c>TagFiles:0:Path /etc/tags.csv, line 3</c>), which
    /// messages name instead of a key under <c>Groups</c>; null for a group under <c>Groups</c>.
    /// </summary>
    internal string? Row { get; init; }
}

/// <summary>When a poll group's values are logged.</summary>
internal enum PollLogMode
{
    /// <summary>After every successful poll.</summary>
    EveryPoll,

    /// <summary>On the first poll and whenever a value changes.</summary>
    OnChange,
}
