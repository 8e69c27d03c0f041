namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// What an output needs of the links and poll groups it carries — a name that can be a topic level or a metric name, a
/// group that can be written — added to the <c>HostLink</c> section's check. That check applies every rule to every
/// enabled link and to every group it polls and accepts, under <c>Groups</c> and from tag files alike, once, whichever
/// outputs added the rule.
/// </summary>
internal interface IGroupRule
{
    /// <summary>Adds the problems of an enabled link's name to <paramref name="failures"/>.</summary>
    /// <param name="name">The link's name.</param>
    /// <param name="path">The link's key, <c>HostLink:Links:{name}</c>.</param>
    /// <param name="failures">Where the problems go, each naming its key.</param>
    void CheckLink(string name, string path, List<string> failures)
    {
    }

    /// <summary>Adds the problems of a poll group of an enabled link to <paramref name="failures"/>.</summary>
    /// <param name="group">The group, and where it is written.</param>
    /// <param name="link">Its link.</param>
    /// <param name="failures">Where the problems go, each naming its key (<see cref="ConfiguredGroup.Key"/>).</param>
    void CheckGroup(ConfiguredGroup group, LinkOptions link, List<string> failures);
}
