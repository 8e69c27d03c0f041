using System.Globalization;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The topic contract: values on <c>{prefix}/{link}/{unit}/{tag}</c>, commands on <c>…/{tag}/set</c> with replies on
/// <c>…/{tag}/set/result</c> (unless the command names an MQTT 5 response topic), link states on
/// <c>{prefix}/{link}/status</c> and the worker's state on <c>{prefix}/status/{clientId}</c>.
/// </summary>
internal sealed class MqttTopics
{
    /// <summary>The last level of a command topic.</summary>
    public const string SetLevel = "set";

    /// <summary>The level under a command topic that carries replies.</summary>
    public const string ResultLevel = "result";

    /// <summary>The level of the status topics (a link may not be named so).</summary>
    public const string StatusLevel = "status";

    /// <summary>Creates the topics under <paramref name="prefix"/> for the worker <paramref name="clientId"/>.</summary>
    public MqttTopics(string prefix, string clientId)
    {
        Prefix = prefix;
        WorkerStatus = $"{prefix}/{StatusLevel}/{clientId}";
        WorkerLost = $"{WorkerStatus}/lost";
    }

    /// <summary>The first level(s) of every topic.</summary>
    public string Prefix { get; }

    /// <summary>The worker's own status topic: <c>online</c> (birth) or <c>offline</c> (last will, or a clean stop).</summary>
    public string WorkerStatus { get; }

    /// <summary>Where the worker announces at start how many messages its previous run may have lost (<see cref="LostMessagesPayload"/>).</summary>
    public string WorkerLost { get; }

    /// <summary>The value topic of a tag.</summary>
    public string Tag(string link, int unit, string tag) => $"{Prefix}/{link}/{unit.ToString(CultureInfo.InvariantCulture)}/{tag}";

    /// <summary>The status topic of a link.</summary>
    public string LinkStatus(string link) => $"{Prefix}/{link}/{StatusLevel}";

    /// <summary>The filter a worker subscribes to for the command topics of one of its links.</summary>
    public string CommandFilter(string link) => $"{Prefix}/{link}/+/+/{SetLevel}";

    /// <summary>The default reply topic of a command topic.</summary>
    public static string ResultTopic(string commandTopic) => $"{commandTopic}/{ResultLevel}";

    /// <summary>Splits a command topic into link, unit and tag; false when it is not one under this prefix.</summary>
    public bool TryParseCommand(string topic, out string link, out int unit, out string tag)
    {
        link = tag = "";
        unit = -1;
        if (!topic.StartsWith(Prefix + "/", StringComparison.Ordinal))
        {
            return false;
        }

        string[] levels = topic.Substring(Prefix.Length + 1).Split('/');
        if (levels.Length != 4 || levels[3] != SetLevel
            || !int.TryParse(levels[1], NumberStyles.None, CultureInfo.InvariantCulture, out unit)
            || levels[1] != unit.ToString(CultureInfo.InvariantCulture))
        {
            // Only the spelling the value topics use ("3", not "03").
            unit = -1;
            return false;
        }

        link = levels[0];
        tag = levels[2];
        return true;
    }

    /// <summary>Whether a message can be published on <paramref name="topic"/>: not empty, no wildcard, no NUL.</summary>
    public static bool IsPublishable(string topic)
        => !string.IsNullOrEmpty(topic) && topic.IndexOfAny(['+', '#', '\0']) < 0;

    /// <summary>Why <paramref name="level"/> cannot be one topic level, or null when it can.</summary>
    public static string? LevelProblem(string level)
    {
        if (string.IsNullOrEmpty(level))
        {
            return "is empty";
        }

        foreach (char c in level)
        {
            if (c is '/' or '+' or '#')
            {
                return $"holds '{c}', which MQTT topics reserve ('/' separates levels, '+' and '#' are wildcards)";
            }

            if (char.IsControl(c))
            {
                return "holds a control character";
            }
        }

        return null;
    }
}
