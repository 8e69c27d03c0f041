using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// Checks the <c>Mqtt</c> section before anything starts, naming each bad key by its configuration path. What the JSON
/// output needs of the links and groups (names that are topic levels) is its <see cref="MqttTopicNames"/> rule.
/// </summary>
/// <param name="gateway">The configuration as the gateway reads it.</param>
/// <param name="contentRoot">The host's content root, where relative paths start.</param>
internal sealed class MqttOptionsValidator(GatewayConfiguration gateway, string contentRoot) : SectionValidator<MqttOptions>(gateway, MqttOptions.SectionName)
{
    private static readonly TimeSpan ShortestStatisticsInterval = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan LongestStatisticsInterval = TimeSpan.FromHours(1);

    /// <inheritdoc/>
    protected override bool IsOn(MqttOptions options) => Gateway.IsEnabled(Section);

    /// <inheritdoc/>
    protected override void Check(MqttOptions options, List<string> failures)
    {
        const string root = MqttOptions.SectionName;
        MqttBrokerOptionsValidator.Validate(options, root, failures);
        if (!string.IsNullOrWhiteSpace(options.ClientId) && MqttTopics.LevelProblem(options.ClientId) is { } idProblem)
        {
            failures.Add($"{root}:ClientId '{options.ClientId}' names the worker's status topic ({{TopicPrefix}}/status/{{ClientId}}) and {idProblem}.");
        }

        if (options.QoS is < 0 or > 2)
        {
            failures.Add($"{root}:QoS must be 0, 1 or 2; it is {options.QoS}.");
        }

        ValidatePrefix(options.TopicPrefix, failures);
        if (options.QueueCapacity is < 1 or > 10_000_000)
        {
            failures.Add($"{root}:QueueCapacity must be 1-10000000; it is {options.QueueCapacity}.");
        }

        if (options.StatisticsInterval < ShortestStatisticsInterval || options.StatisticsInterval > LongestStatisticsInterval)
        {
            failures.Add($"{root}:StatisticsInterval must be 1s to 1h; it is {options.StatisticsInterval}.");
        }

        ValidateDurableQueue(options, failures);
        ValidateReplyPrefixes(options, failures);
    }

    private void ValidateDurableQueue(MqttOptions options, List<string> failures)
    {
        const string key = MqttOptions.SectionName + ":DurableQueue";
        DurableQueueOptions? durable = options.DurableQueue;
        if (durable is null)
        {
            return;
        }

        if (durable.MaxMegabytes is < 1 or > 1_048_576)
        {
            failures.Add($"{key}:MaxMegabytes must be 1-1048576 (1 TiB); it is {durable.MaxMegabytes}.");
        }

        if (durable.MaxAge < TimeSpan.FromSeconds(1))
        {
            failures.Add($"{key}:MaxAge must be at least 1s; it is {durable.MaxAge}.");
        }

        if (durable.Enabled && failures.Count == 0)
        {
            // Opened now, so that a directory the service may not write is one line at start, not a crash later.
            string path = options.JournalPath(contentRoot);
            if (SqliteOutboundJournal.Problem(path) is { } problem)
            {
                failures.Add($"{key}:Enabled: the queue's database {path} cannot be opened: {problem}. Set {MqttOptions.SectionName}:StateDirectory to a directory the gateway may write.");
            }
        }
    }

    private static void ValidateReplyPrefixes(MqttOptions options, List<string> failures)
    {
        List<string> prefixes = options.Writes?.ReplyPrefixes ?? [];
        for (int i = 0; i < prefixes.Count; i++)
        {
            string key = $"{MqttOptions.SectionName}:Writes:ReplyPrefixes:{i}";
            string prefix = prefixes[i] ?? "";
            string? levelProblem = prefix.Split('/').Select(l => l.Length == 0 ? "is empty (a leading, trailing or doubled '/')" : MqttTopics.LevelProblem(l)).FirstOrDefault(p => p is not null);
            if (prefix.Length == 0 || prefix.StartsWith('$') || levelProblem is not null)
            {
                failures.Add($"{key} '{prefix}' is not a topic prefix: {(prefix.Length == 0 ? "it is empty" : prefix.StartsWith('$') ? "'$' topics are the broker's" : "a level " + levelProblem)}; write levels without wildcards, such as scada/replies.");
            }
            else if (Overlaps(prefix, options.TopicPrefix))
            {
                failures.Add($"{key} '{prefix}' overlaps {MqttOptions.SectionName}:TopicPrefix '{options.TopicPrefix}': replies there could land on value, status or command topics. Use a prefix of its own, such as scada/replies.");
            }
        }
    }

    /// <summary>Whether one topic prefix contains the other, level by level.</summary>
    private static bool Overlaps(string a, string? b)
    {
        if (string.IsNullOrEmpty(b))
        {
            return false;
        }

        return a == b || a.StartsWith(b + "/", StringComparison.Ordinal) || b.StartsWith(a + "/", StringComparison.Ordinal);
    }

    private static void ValidatePrefix(string? prefix, List<string> failures)
    {
        const string key = MqttOptions.SectionName + ":TopicPrefix";
        if (string.IsNullOrEmpty(prefix))
        {
            failures.Add($"{key} is empty; set the first topic level(s), e.g. omronhostlink or plant1/hostlink.");
            return;
        }

        if (prefix.StartsWith('$'))
        {
            failures.Add($"{key} '{prefix}' starts with '$', which brokers reserve ($SYS).");
            return;
        }

        foreach (string level in prefix.Split('/'))
        {
            if (MqttTopics.LevelProblem(level) is { } problem)
            {
                failures.Add($"{key} '{prefix}': a level {(level.Length == 0 ? "is empty (a leading, trailing or doubled '/')" : problem)}.");
                return;
            }
        }
    }
}
