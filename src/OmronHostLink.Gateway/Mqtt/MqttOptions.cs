using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The <c>Mqtt</c> section: publish tag values to an MQTT broker and, if allowed, accept writes. Without the section
/// (or with <c>Enabled: false</c>) the worker only logs.
/// </summary>
internal sealed class MqttOptions : MqttBrokerOptions
{
    /// <summary>The configuration section these options bind to.</summary>
    public const string SectionName = "Mqtt";

    /// <summary>False to keep the section in the file without connecting. Default true.</summary>
    public bool Enabled { get; set; } = true;

    /// <summary>Quality of service of everything the worker publishes and subscribes to: 0, 1 (default) or 2.</summary>
    public int QoS { get; set; } = 1;

    /// <summary>The first topic level(s): topics are <c>{TopicPrefix}/{link}/{unit}/{tag}</c>. Default <c>omronhostlink</c>.</summary>
    public string TopicPrefix { get; set; } = "omronhostlink";

    /// <summary>How many messages wait for the broker at most; beyond it the oldest are dropped (and counted). Default 10 000.</summary>
    public int QueueCapacity { get; set; } = 10_000;

    /// <summary>
    /// Where the gateway keeps what must outlive it: the durable queue and the count of unsent messages. Default: the
    /// directory systemd gives the service (<c>STATE_DIRECTORY</c>, from <c>StateDirectory=</c>); otherwise
    /// <c>%ProgramData%\OmronHostLink.Gateway</c> on Windows and <c>state</c> below the content root elsewhere.
    /// </summary>
    public string? StateDirectory { get; set; }

    /// <summary>The outage queue on disk (off by default).</summary>
    public DurableQueueOptions DurableQueue { get; set; } = new();

    /// <summary>How often the statistics of every link and unit are published (and at once when a unit's state changes). Default 10 s; 1 s to 1 h.</summary>
    public TimeSpan StatisticsInterval { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>Writes from MQTT (off by default).</summary>
    public MqttWriteOptions Writes { get; set; } = new();

    /// <summary>
    /// The client id in effect, unique per worker; it also names the worker's status topic. Default
    /// <c>omronhostlink-{machine name}</c>.
    /// </summary>
    public override string ClientIdOrDefault => string.IsNullOrWhiteSpace(ClientId) ? DefaultClientId() : ClientId;

    private static string DefaultClientId()
    {
        // Machine names may hold characters a topic level should not; keep letters, digits, '-' and '_'.
        var name = new string(Environment.MachineName.ToLowerInvariant().Select(c => char.IsAsciiLetterOrDigit(c) || c is '-' or '_' ? c : '-').ToArray());
        return "omronhostlink-" + name;
    }
}

/// <summary>The <c>Mqtt:Writes</c> section.</summary>
internal sealed class MqttWriteOptions
{
    /// <summary>
    /// Accept write commands on <c>{prefix}/{link}/{unit}/{tag}/set</c> for the poll groups marked <c>Writable</c>.
    /// Default false: the worker does not subscribe to any command topic.
    /// </summary>
    public bool Enabled { get; set; }

    /// <summary>
    /// Topic prefixes a command's MQTT 5 response topic may lie under, such as <c>scada/replies</c>: a reply goes to the
    /// command's own result topic (<c>{command topic}/result</c>) or under one of these, never elsewhere. A command whose
    /// response topic is anywhere else is refused (and answered on its result topic). None by default.
    /// </summary>
    public List<string> ReplyPrefixes { get; set; } = [];
}
