namespace OmronHostLink.Gateway.Configuration;

/// <summary>A poll group as the <c>HostLink</c> section gives it, and where it is written, for messages.</summary>
/// <param name="LinkPath">The link's key, <c>HostLink:Links:{link}</c>.</param>
/// <param name="Name">The group's (tag's) name.</param>
/// <param name="Options">The group.</param>
internal sealed record ConfiguredGroup(string LinkPath, string Name, PollGroupOptions Options)
{
    /// <summary>
    /// The key that names the group in a message: <c>HostLink:Links:plc:Groups:levels</c>, or for a row of a tag file
    /// the file and line, <c>HostLink:Links:plc:TagFiles:0:Path /etc/tags.csv, line 3: tag 'levels'</c>.
    /// </summary>
    public string Key => Options.Row is { } row ? $"{LinkPath}:{row}: tag '{Name}'" : $"{LinkPath}:Groups:{Name}";

    /// <summary>The key of one of the group's settings: <c>…:Groups:levels:Writable</c>, or <c>…, line 3: tag 'levels' (Writable)</c>.</summary>
    public string KeyOf(string setting) => Options.Row is null ? $"{Key}:{setting}" : $"{Key} ({setting})";

    /// <summary>The groups of an enabled link, configured and imported, in the order the gateway polls them.</summary>
    public static IEnumerable<ConfiguredGroup> Of(string linkName, LinkOptions link)
    {
        string path = $"{GatewayOptions.SectionName}:Links:{linkName}";
        foreach ((string name, PollGroupOptions? group) in link.Groups)
        {
            if (group is not null)
            {
                yield return new ConfiguredGroup(path, name, group);
            }
        }
    }
}
