using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Outputs;

/// <summary>The tags of the enabled links, from the validated <c>HostLink</c> section, looked up as topics name them.</summary>
internal sealed class TagCatalog
{
    private readonly Dictionary<(string Link, int Unit, string Name), TagDefinition> _tags = new();

    /// <summary>Builds the catalogue from validated options.</summary>
    public TagCatalog(GatewayOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        foreach ((string link, LinkOptions linkOptions) in options.Links.OrderBy(l => l.Key, StringComparer.Ordinal))
        {
            if (linkOptions is not { Enabled: true })
            {
                continue;
            }

            Links.Add(link);
            foreach ((string name, PollGroupOptions g) in linkOptions.Groups)
            {
                PlcValueTypes.TryParse(g.Type, out PlcValueType type);
                var tag = new TagDefinition(link, g.Unit, name, PlcAddress.Parse(g.Address), type, g.Count, linkOptions.WordOrder, g.Writable, linkOptions.CommandSet);
                _tags[(link, g.Unit, name)] = tag;
            }
        }
    }

    /// <summary>The enabled links' names.</summary>
    public List<string> Links { get; } = new();

    /// <summary>All tags.</summary>
    public IEnumerable<TagDefinition> Tags => _tags.Values;

    /// <summary>Finds a tag by its names as a topic spells them (exact, case-sensitive like MQTT topics).</summary>
    public TagDefinition? Find(string link, int unit, string name)
        => _tags.TryGetValue((link, unit, name), out TagDefinition? tag) ? tag : null;
}
