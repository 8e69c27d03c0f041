using OmronHostLink.Gateway.Broker;


namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The <c>Sparkplug</c> section: publish the tags as a Sparkplug B edge node (for Ignition's MQTT Engine and other
/// Sparkplug host applications), beside or instead of the JSON output. Its own MQTT connection, because the edge
/// node's death certificate (NDEATH) is that connection's will; its broker keys (<see cref="MqttBrokerOptions"/>) are
/// those of the <c>Mqtt</c> section. Without the section (or with <c>Enabled: false</c>) nothing is published.
/// </summary>
internal sealed class SparkplugOptions : MqttBrokerOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "Sparkplug";

    /// <summary>False to keep the section in the file without connecting. Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>The Sparkplug group the edge node belongs to (the second topic level). Required.</summary>
    public string GroupId { get; set; } = "";

    /// <summary>The edge node's id (the fourth topic level): this gateway. Required.</summary>
    public string EdgeNodeId { get; set; } = "";

    /// <summary>
    /// The primary host application's id (its <c>spBv1.0/STATE/{id}</c> topic; Ignition's MQTT Engine shows it as the
    /// primary host id). When set, the edge node publishes its births only while that host says it is online, and
    /// ends its session when the host goes offline. Default none: births at once on every connection.
    /// </summary>
    public string? PrimaryHostId { get; set; }

    /// <summary>
    /// The primary host application speaks Sparkplug 2.2's STATE: <c>STATE/{PrimaryHostId}</c> (outside the
    /// <c>spBv1.0</c> namespace) with the plain text <c>ONLINE</c> or <c>OFFLINE</c>, as older MQTT Engine versions
    /// publish it. Default false: Sparkplug 3.0's <c>spBv1.0/STATE/{PrimaryHostId}</c> with its JSON payload.
    /// </summary>
    public bool PrimaryHostLegacyState { get; set; }

    /// <summary>
    /// Where the gateway keeps what must outlive it: the durable store of changes (<see cref="StoreAndForward"/>) and
    /// the count of changes held in memory only. Default as <c>Mqtt:StateDirectory</c>: systemd's
    /// <c>STATE_DIRECTORY</c>, else <c>%ProgramData%\OmronHostLink.Gateway</c> on Windows and <c>state</c> below the
    /// content root elsewhere.
    /// </summary>
    public string? StateDirectory { get; set; }

    /// <summary>What is kept while the node has no primary host or no broker, and sent as history afterwards.</summary>
    public SparkplugStoreOptions StoreAndForward { get; set; } = new();

    /// <summary>Device commands (DCMD) that write tags.</summary>
    public SparkplugWriteOptions Writes { get; set; } = new();

    /// <summary>The client id in effect. Default <c>{GroupId}-{EdgeNodeId}</c>.</summary>
    public override string ClientIdOrDefault => string.IsNullOrWhiteSpace(ClientId) ? $"{GroupId}-{EdgeNodeId}" : ClientId;
}

/// <summary>
/// The <c>Sparkplug:StoreAndForward</c> section: while the edge node has no session (no broker, or the primary host
/// application offline), every change of a metric is kept with the time it was read from the PLC, and after the next
/// births it is published as DDATA with <c>is_historical</c> true, oldest first, between the live messages.
/// </summary>
internal sealed class SparkplugStoreOptions
{
    /// <summary>Keep the changes. Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>The most changes kept (1-10000000); beyond it the oldest are dropped, counted and announced. Default 100 000.</summary>
    public int Capacity { get; set; } = 100_000;

    /// <summary>
    /// Keep them on disk (SQLite, <c>{StateDirectory}/{ClientId}.sparkplug.queue.db</c>), so that a crash or a restart
    /// loses none. Default false: in memory, and a run that ends with changes kept makes the next run announce how many
    /// were lost.
    /// </summary>
    public bool Durable { get; set; }

    /// <summary>The most the kept changes may take, in megabytes (1-1048576); beyond it the oldest are dropped. Default 256.</summary>
    public int MaxMegabytes { get; set; } = 256;

    /// <summary>How long a change may be kept; older ones are dropped, counted and announced. Default 168 h (a week).</summary>
    public TimeSpan MaxAge { get; set; } = TimeSpan.FromDays(7);
}

/// <summary>The <c>Sparkplug:Writes</c> section.</summary>
internal sealed class SparkplugWriteOptions
{
    /// <summary>
    /// Carry out DCMD metric writes to the tags configured <c>Writable</c> (the same allowlist and value checks as MQTT
    /// JSON writes). Default false: every DCMD is refused and logged, and nothing reaches a PLC.
    /// </summary>
    public bool Enabled { get; set; }
}
