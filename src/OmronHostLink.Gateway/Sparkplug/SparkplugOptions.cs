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

    /// <summary>Device commands (DCMD) that write tags.</summary>
    public SparkplugWriteOptions Writes { get; set; } = new();

    /// <summary>The client id in effect. Default <c>{GroupId}-{EdgeNodeId}</c>.</summary>
    public override string ClientIdOrDefault => string.IsNullOrWhiteSpace(ClientId) ? $"{GroupId}-{EdgeNodeId}" : ClientId;
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
