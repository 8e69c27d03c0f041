using System.Globalization;
using System.Text.Json.Nodes;
using OmronHostLink.Gateway.Tests.Mqtt;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>A metric's value as a host application received it.</summary>
/// <param name="Device">The device id.</param>
/// <param name="Metric">The metric's name (resolved through the birth's aliases for data).</param>
/// <param name="Value">The value as text.</param>
/// <param name="Timestamp">The metric's timestamp: when the PLC was read (ms since 1970).</param>
/// <param name="Historical">Its <c>is_historical</c> flag.</param>
/// <param name="Birth">Carried by a DBIRTH (else a DDATA).</param>
/// <param name="Index">The position of its message among those received.</param>
internal sealed record HostSample(string Device, string Metric, string Value, long Timestamp, bool Historical, bool Birth, int Index);

/// <summary>
/// What a Sparkplug host application makes of an edge node's messages, decoded by Eclipse Tahu: every metric value it
/// received, and every breach of the rules a host checks — seq not following on from the last message of the session
/// (NBIRTH is 0, each next one more, 255 wrapping to 0), data for a device not born in the session, an alias the
/// device's birth did not declare.
/// </summary>
internal sealed class SparkplugHostView
{
    private SparkplugHostView(IReadOnlyList<HostSample> samples, IReadOnlyList<string> violations, IReadOnlyList<long> droppedAnnounced)
    {
        Samples = samples;
        Violations = violations;
        DroppedAnnounced = droppedAnnounced;
    }

    /// <summary>Every metric value received, in order.</summary>
    public IReadOnlyList<HostSample> Samples { get; }

    /// <summary>The rules broken, each with where.</summary>
    public IReadOnlyList<string> Violations { get; }

    /// <summary>Every value of the node metric <c>Store and Forward/Dropped</c> received (NBIRTH and NDATA).</summary>
    public IReadOnlyList<long> DroppedAnnounced { get; }

    /// <summary>Reads the node's messages among <paramref name="messages"/>.</summary>
    public static async Task<SparkplugHostView> ReadAsync(TahuCodec tahu, IReadOnlyList<ReceivedMessage> messages)
    {
        var samples = new List<HostSample>();
        var violations = new List<string>();
        var dropped = new List<long>();
        long? lastSeq = null;
        var aliases = new Dictionary<string, Dictionary<string, string>>(StringComparer.Ordinal);
        string node = $"{SparkplugEndToEndTests.Namespace}/";
        for (int i = 0; i < messages.Count; i++)
        {
            ReceivedMessage message = messages[i];
            string[] parts = message.Topic.Split('/');
            if (!message.Topic.StartsWith(node, StringComparison.Ordinal) || parts.Length < 4 || parts[3] != SparkplugEndToEndTests.Node || parts[2].EndsWith("CMD", StringComparison.Ordinal))
            {
                continue;
            }

            string type = parts[2];
            JsonObject payload = await tahu.DecodeAsync(message.Bytes!);
            if (type == "NDEATH")
            {
                lastSeq = null;
                aliases.Clear();
                continue;
            }

            long seq = long.Parse((string)payload["seq"]!, CultureInfo.InvariantCulture);
            if (type == "NBIRTH")
            {
                if (seq != 0)
                {
                    violations.Add($"message {i}: NBIRTH with seq {seq}");
                }

                aliases.Clear();
                dropped.AddRange(SparkplugEndToEndTests.Metrics(payload).Where(m => (string?)m["name"] == "Store and Forward/Dropped").Select(m => long.Parse((string)m["value"]!, CultureInfo.InvariantCulture)));
            }
            else if (lastSeq is null)
            {
                violations.Add($"message {i}: {type} before any NBIRTH");
            }
            else if (seq != (lastSeq + 1) % 256)
            {
                violations.Add($"message {i}: {type} with seq {seq} after {lastSeq}");
            }

            lastSeq = seq;
            if (type == "NDATA")
            {
                dropped.AddRange(SparkplugEndToEndTests.Metrics(payload).Where(m => (string?)m["name"] == "Store and Forward/Dropped").Select(m => long.Parse((string)m["value"]!, CultureInfo.InvariantCulture)));
                continue;
            }

            if (parts.Length != 5)
            {
                continue;
            }

            string device = parts[4];
            if (type == "DBIRTH")
            {
                var map = new Dictionary<string, string>(StringComparer.Ordinal);
                foreach (JsonObject metric in SparkplugEndToEndTests.Metrics(payload))
                {
                    map[(string)metric["alias"]!] = (string)metric["name"]!;
                    samples.Add(Sample(device, (string)metric["name"]!, metric, birth: true, i));
                }

                aliases[device] = map;
            }
            else if (type == "DDEATH")
            {
                aliases.Remove(device);
            }
            else if (type == "DDATA")
            {
                if (!aliases.TryGetValue(device, out Dictionary<string, string>? map))
                {
                    violations.Add($"message {i}: DDATA of {device}, not born in this session");
                    continue;
                }

                foreach (JsonObject metric in SparkplugEndToEndTests.Metrics(payload))
                {
                    string alias = (string)metric["alias"]!;
                    if (!map.TryGetValue(alias, out string? name))
                    {
                        violations.Add($"message {i}: DDATA of {device} with alias {alias}, which its birth did not declare");
                        continue;
                    }

                    samples.Add(Sample(device, name, metric, birth: false, i));
                }
            }
        }

        return new SparkplugHostView(samples, violations, dropped);
    }

    /// <summary>The values of <paramref name="metric"/> received, in order.</summary>
    public IReadOnlyList<HostSample> Of(string metric) => Samples.Where(s => s.Metric == metric).ToArray();

    private static HostSample Sample(string device, string name, JsonObject metric, bool birth, int index)
        => new(
            device,
            name,
            SparkplugEndToEndTests.ValueText(metric),
            long.Parse((string)metric["timestamp"]!, CultureInfo.InvariantCulture),
            metric["isHistorical"] is JsonValue h && h.GetValue<bool>(),
            birth,
            index);
}
