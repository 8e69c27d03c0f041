using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Checks the <c>Sparkplug</c> section before anything starts, naming each bad key: the ids and the broker settings.
/// What the edge node needs of the links and groups (names that are device ids and metric names) is its
/// <see cref="SparkplugNames"/> rule.
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
/// <param name="contentRoot">The host's content root, where relative paths start.</param>
internal sealed class SparkplugOptionsValidator(GatewayConfiguration gateway, string contentRoot) : SectionValidator<SparkplugOptions>(gateway, SparkplugOptions.SectionName)
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
        else if (options.PrimaryHostLegacyState)
        {
            failures.Add($"{Root}:PrimaryHostLegacyState is set without {Root}:PrimaryHostId; set the id of the primary host application whose STATE/{{id}} to follow.");
        }

        MqttBrokerOptionsValidator.Validate(options, Root, failures);
        ValidateStore(options, failures);
    }

    private void ValidateStore(SparkplugOptions options, List<string> failures)
    {
        const string key = Root + ":StoreAndForward";
        if (options.StoreAndForward is not { } store)
        {
            return;
        }

        if (store.Capacity is < 1 or > 10_000_000)
        {
            failures.Add($"{key}:Capacity must be 1-10000000; it is {store.Capacity}.");
        }

        if (store.MaxMegabytes is < 1 or > 1_048_576)
        {
            failures.Add($"{key}:MaxMegabytes must be 1-1048576 (1 TiB); it is {store.MaxMegabytes}.");
        }

        if (store.MaxAge < TimeSpan.FromSeconds(1))
        {
            failures.Add($"{key}:MaxAge must be at least 1s; it is {store.MaxAge}.");
        }

        if (store.Durable && !store.Enabled)
        {
            failures.Add($"{key}:Durable is true but {key}:Enabled is false; nothing would be kept.");
        }
        else if (store.Durable && failures.Count == 0)
        {
            // Opened now, so that a directory the service may not write is one line at start, not a crash later.
            string path = SparkplugHistory.JournalPath(options, contentRoot);
            if (Queue.SqliteOutboundJournal.Problem(path, Root) is { } problem)
            {
                failures.Add($"{key}:Durable: the store's database {path} cannot be opened: {problem}. Set {Root}:StateDirectory to a directory the gateway may write.");
            }
        }
    }

    private static void Id(string key, string? id, string example, List<string> failures)
    {
        if (SparkplugTopic.Check(id) is { } problem)
        {
            failures.Add($"{Root}:{key} '{id}' cannot be a Sparkplug id: {problem}; set {example}.");
        }
    }
}
