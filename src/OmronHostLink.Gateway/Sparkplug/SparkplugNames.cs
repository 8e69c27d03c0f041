using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>What the edge node needs of the links and groups: link names start device ids, group names are metric names.</summary>
internal sealed class SparkplugNames : IGroupRule
{
    /// <inheritdoc/>
    public void CheckLink(string name, string path, List<string> failures)
    {
        if (SparkplugTopic.Check(name) is { } problem)
        {
            failures.Add($"{path}: the link's name starts the Sparkplug device ids ({{link}}-{{unit}}) and {problem}.");
        }
    }

    /// <inheritdoc/>
    public void CheckGroup(ConfiguredGroup group, LinkOptions link, List<string> failures)
    {
        if (SparkplugTopic.Check(group.Name) is { } problem)
        {
            failures.Add($"{group.Key}: the group's name is a Sparkplug metric name and {problem}.");
        }
    }
}
