using System.Globalization;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// A PLC unit as a Sparkplug device (<c>{link}-{unit}</c>): its metrics, one per tag of one value and one per value of a
/// tag of several (<c>name/0</c>, <c>name/1</c>…), in alias order (<see cref="FromCatalog"/>).
/// </summary>
internal sealed class SparkplugDevice
{
    private readonly Dictionary<string, SparkplugMetric> _byName;
    private readonly Dictionary<ulong, SparkplugMetric> _byAlias;

    internal SparkplugDevice(string link, int unit, IReadOnlyList<SparkplugMetric> metrics, IReadOnlyDictionary<string, TagDefinition> tags)
    {
        Link = link;
        Unit = unit;
        Id = DeviceId(link, unit);
        Metrics = metrics;
        Tags = tags;
        _byName = metrics.ToDictionary(m => m.Name, StringComparer.Ordinal);
        _byAlias = metrics.ToDictionary(m => m.Alias);
    }

    /// <summary>The link's configured name.</summary>
    public string Link { get; }

    /// <summary>The unit number.</summary>
    public int Unit { get; }

    /// <summary>The device id (the fifth topic level).</summary>
    public string Id { get; }

    /// <summary>The device's metrics.</summary>
    public IReadOnlyList<SparkplugMetric> Metrics { get; }

    /// <summary>The tags behind the metrics, by tag name.</summary>
    public IReadOnlyDictionary<string, TagDefinition> Tags { get; }

    /// <summary>The metric named <paramref name="name"/>; null when the device has none.</summary>
    public SparkplugMetric? Metric(string name) => _byName.GetValueOrDefault(name);

    /// <summary>The metric of alias <paramref name="alias"/>; null when the device has none.</summary>
    public SparkplugMetric? Metric(ulong alias) => _byAlias.GetValueOrDefault(alias);

    /// <summary>The device id of a unit: <c>{link}-{unit}</c>.</summary>
    public static string DeviceId(string link, int unit) => $"{link}-{unit.ToString(CultureInfo.InvariantCulture)}";

    /// <summary>
    /// The metrics of the catalogue's tags, one device per unit. Aliases are numbered from 1: devices by link name
    /// (ordinal) and unit number, within a device the tags by name (ordinal), the values of a tag of several in order.
    /// The order is the names', not the configuration file's: .NET's configuration gives a section's keys sorted, and
    /// tag files add their rows beside them.
    /// </summary>
    public static IReadOnlyList<SparkplugDevice> FromCatalog(TagCatalog catalog)
    {
        ArgumentNullException.ThrowIfNull(catalog);
        var devices = new List<SparkplugDevice>();
        ulong alias = 1;
        foreach (IGrouping<(string Link, int Unit), TagDefinition> unit in catalog.Tags.GroupBy(t => (t.Link, t.Unit)).OrderBy(g => g.Key.Link, StringComparer.Ordinal).ThenBy(g => g.Key.Unit))
        {
            var metrics = new List<SparkplugMetric>();
            var tags = new Dictionary<string, TagDefinition>(StringComparer.Ordinal);
            foreach (TagDefinition tag in unit.OrderBy(t => t.Name, StringComparer.Ordinal))
            {
                tags[tag.Name] = tag;
                SparkplugDataType type = SparkplugValues.DataTypeOf(tag.Type);
                if (ValueCount(tag) == 1)
                {
                    metrics.Add(new SparkplugMetric(tag.Name, alias++, type, tag.Name, -1, tag.Writable));
                }
                else
                {
                    for (int i = 0; i < tag.Count; i++)
                    {
                        metrics.Add(new SparkplugMetric($"{tag.Name}/{i.ToString(CultureInfo.InvariantCulture)}", alias++, type, tag.Name, i, tag.Writable));
                    }
                }
            }

            devices.Add(new SparkplugDevice(unit.Key.Link, unit.Key.Unit, metrics, tags));
        }

        return devices;
    }

    /// <summary>How many metrics a tag is: one for a single value, text or completion flag; else one per value.</summary>
    private static int ValueCount(TagDefinition tag)
        => tag.Type == PlcValueType.String || tag.Count == 1 || (tag.Type == PlcValueType.Bit && tag.Address.Area is PlcArea.Timer or PlcArea.Counter)
            ? 1
            : tag.Count;
}
