using System.Text.RegularExpressions;

namespace OmronHostLink.Gateway.Tests.Broker;

/// <summary>
/// The connections of MQTT clients as brokers that share one log file wrote them (<see cref="MosquittoSettings.SharedLogFile"/>,
/// each line tagged with its broker): appends to one file keep the order in which they happened, so the file says, at
/// every moment, which brokers a client id is connected to. A marker line <c>TAG:0: killed</c> written by the test
/// before it kills a broker ends that broker's connections, as its <c>terminating</c> line does.
/// </summary>
internal static partial class ConnectionTimeline
{
    /// <summary>Writes the marker that ends <paramref name="tag"/>'s connections (before killing its broker with SIGKILL).</summary>
    public static void MarkKilled(string file, string tag) => File.AppendAllText(file, $"{tag}:0: killed by the test{Environment.NewLine}");

    /// <summary>Reads the file: each connection of <paramref name="clientId"/> in order, and the moments it was connected to two brokers at once.</summary>
    public static (IReadOnlyList<string> Connections, IReadOnlyList<string> Overlaps) Read(string file, string clientId)
    {
        var connectedTo = new HashSet<string>(StringComparer.Ordinal);
        var connections = new List<string>();
        var overlaps = new List<string>();
        foreach (string line in File.ReadAllLines(file))
        {
            Match tagged = Tagged().Match(line);
            if (!tagged.Success)
            {
                continue;
            }

            string tag = tagged.Groups["tag"].Value;
            string text = tagged.Groups["text"].Value;
            if (text.StartsWith("mosquitto version", StringComparison.Ordinal) && text.EndsWith("terminating", StringComparison.Ordinal)
                || text == "killed by the test")
            {
                connectedTo.Remove(tag);
            }
            else if (Connected().Match(text) is { Success: true } connected && connected.Groups["id"].Value == clientId)
            {
                connectedTo.Add(tag);
                connections.Add(tag);
                if (connectedTo.Count > 1)
                {
                    overlaps.Add($"{line} (connected to {string.Join(" and ", connectedTo)})");
                }
            }
            else if (Ended().Match(text) is { Success: true } ended && ended.Groups["id"].Value == clientId)
            {
                connectedTo.Remove(tag);
            }
        }

        return (connections, overlaps);
    }

    [GeneratedRegex(@"^(?<tag>[A-Za-z]+):\d+: (?<text>.*)$")]
    private static partial Regex Tagged();

    [GeneratedRegex(@"^New client connected from \S+ as (?<id>\S+) \(")]
    private static partial Regex Connected();

    [GeneratedRegex(@"^(Client (?<id>\S+) (disconnected|closed its connection|has exceeded timeout|already connected)|Socket error on client (?<id>\S+),)")]
    private static partial Regex Ended();
}
