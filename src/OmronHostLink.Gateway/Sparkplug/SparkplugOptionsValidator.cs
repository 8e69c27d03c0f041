using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Checks the <c>Sparkplug</c> section before anything starts, naming each bad key: the section as written (unknown
/// keys, values of the wrong type), the ids, the broker settings, and that the names of links and poll groups can be
/// device ids and metric names and the groups marked <c>Writable</c> can be written.
/// </summary>
/// <param name="configuration">The configuration; the <c>HostLink</c> section is read from it.</param>
public sealed class SparkplugOptionsValidator(IConfiguration configuration) : IValidateOptions<SparkplugOptions>
{
    private const string Root = SparkplugOptions.SectionName;

    /// <inheritdoc/>
    public ValidateOptionsResult Validate(string? name, SparkplugOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        if (!options.Enabled)
        {
            return ValidateOptionsResult.Success;
        }

        var failures = new List<string>(ConfigurationSchema.Check(configuration.GetSection(Root), typeof(SparkplugOptions)));
        Id(nameof(SparkplugOptions.GroupId), options.GroupId, "the group the edge node belongs to, such as Plant1", failures);
        Id(nameof(SparkplugOptions.EdgeNodeId), options.EdgeNodeId, "this gateway's name in the group, such as hostlink-gw1", failures);
        if (!string.IsNullOrEmpty(options.PrimaryHostId))
        {
            Id(nameof(SparkplugOptions.PrimaryHostId), options.PrimaryHostId, "the primary host application's id (MQTT Engine's primary host id), such as IamHost", failures);
        }

        MqttBrokerOptionsValidator.Validate(options, Root, failures);
        ValidateTags(failures);
        return failures.Count == 0 ? ValidateOptionsResult.Success : ValidateOptionsResult.Fail(failures);
    }

    private static void Id(string key, string? id, string example, List<string> failures)
    {
        if (SparkplugTopic.Check(id) is { } problem)
        {
            failures.Add($"{Root}:{key} '{id}' cannot be a Sparkplug id: {problem}; set {example}.");
        }
    }

    private void ValidateTags(List<string> failures)
    {
        var worker = new GatewayOptions();
        LinkClients.Bind(configuration.GetSection(GatewayOptions.SectionName), worker);
        foreach ((string linkName, LinkOptions? link) in worker.Links)
        {
            if (link is not { Enabled: true })
            {
                continue;
            }

            string path = $"{GatewayOptions.SectionName}:Links:{linkName}";
            if (SparkplugTopic.Check(linkName) is { } linkProblem)
            {
                failures.Add($"{path}: the link's name starts the Sparkplug device ids ({{link}}-{{unit}}) and {linkProblem}.");
            }

            foreach ((string groupName, PollGroupOptions? group) in link.Groups)
            {
                if (group is null)
                {
                    continue;
                }

                string groupPath = $"{path}:Groups:{groupName}";
                if (SparkplugTopic.Check(groupName) is { } groupProblem)
                {
                    failures.Add($"{groupPath}: the group's name is a Sparkplug metric name and {groupProblem}.");
                }

                if (group.Writable)
                {
                    WritableRule.Validate(groupPath, group, link.CommandSet, failures);
                }
            }
        }
    }
}
