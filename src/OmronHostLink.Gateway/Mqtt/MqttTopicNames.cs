using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// What the JSON output needs of the links and groups: their names are topic levels (<c>{prefix}/{link}/{unit}/{tag}</c>),
/// and no link is named <c>status</c>, the level of the status topics.
/// </summary>
internal sealed class MqttTopicNames : IGroupRule
{
    /// <inheritdoc/>
    public void CheckLink(string name, string path, List<string> failures)
    {
        if (MqttTopics.LevelProblem(name) is { } problem)
        {
            failures.Add($"{path}: the link's name is a topic level for MQTT and {problem}.");
        }
        else if (name == MqttTopics.StatusLevel)
        {
            failures.Add($"{path}: a link cannot be named '{MqttTopics.StatusLevel}' with MQTT on: {{prefix}}/status/… holds the workers' status topics.");
        }
    }

    /// <inheritdoc/>
    public void CheckGroup(ConfiguredGroup group, LinkOptions link, List<string> failures)
    {
        if (MqttTopics.LevelProblem(group.Name) is { } problem)
        {
            failures.Add($"{group.Key}: the group's name is a topic level for MQTT and {problem}.");
        }
    }
}
