using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Checks the <c>Sparkplug</c> section before anything starts, naming each bad key: the ids and the broker settings.
/// What the edge node needs of the links and groups (names that are device ids and metric names) is its
/// <see cref="SparkplugNames"/> rule.
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
internal sealed class SparkplugOptionsValidator(GatewayConfiguration gateway) : SectionValidator<SparkplugOptions>(gateway, SparkplugOptions.SectionName)
{
    private const string Root = SparkplugOptions.SectionName;

    /// <inheritdoc/>
    protected override bool IsOn(SparkplugOptions options) => Gateway.IsEnabled(Section);

    /// <inheritdoc/>
    protected override void Check(SparkplugOptions options, List<string> failures)
    {
        Id(nameof(SparkplugOptions.GroupId), options.GroupId, "the group the edge node belongs to, such as Plant1", failures);
        Id(nameof(SparkplugOptions.EdgeNodeId), options.EdgeNodeId, "this gateway's name in the group, such as hostlink-gw1", failures);
        if (!string.IsNullOrEmpty(options.PrimaryHostId))
        {
            Id(nameof(SparkplugOptions.PrimaryHostId), options.PrimaryHostId, "the primary host application's id (MQTT Engine's primary host id), such as IamHost", failures);
        }

        MqttBrokerOptionsValidator.Validate(options, Root, failures);
    }

    private static void Id(string key, string? id, string example, List<string> failures)
    {
        if (SparkplugTopic.Check(id) is { } problem)
        {
            failures.Add($"{Root}:{key} '{id}' cannot be a Sparkplug id: {problem}; set {example}.");
        }
    }
}
