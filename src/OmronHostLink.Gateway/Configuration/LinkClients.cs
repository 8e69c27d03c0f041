using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;

namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// One <see cref="HostLinkClient"/> per enabled link, registered through OmronHostLink.DependencyInjection as a keyed
/// singleton named after the link: the link's section is a client section of the DI package (<c>Serial</c>,
/// <c>Tcp</c>, <c>CommandSet</c>, …) with the worker's own <c>Enabled</c>, <c>Backoff</c> and <c>Groups</c> beside.
/// </summary>
internal static class LinkClients
{
    /// <summary>
    /// Registers the clients of the enabled links of <paramref name="gateway"/>'s <c>HostLink</c> section. Call it only
    /// for a section that passes its check: an invalid section registers none, and the host then fails at start with
    /// the gateway's own messages, which name the link's keys, and with nothing else.
    /// </summary>
    public static IServiceCollection AddLinkClients(this IServiceCollection services, GatewayConfiguration gateway)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        IConfigurationSection section = gateway.Root.GetSection(GatewayOptions.SectionName);
        foreach ((string name, LinkOptions link) in gateway.HostLink.Links)
        {
            if (link.Enabled)
            {
                IConfigurationSection linkSection = section.GetSection($"Links:{name}");
                services.AddHostLinkClient(name, settings => settings.Read(ClientKeys(linkSection)));
            }
        }

        return services;
    }

    /// <summary>Binds the <c>HostLink</c> section: the worker's keys, and each link's client keys into its <see cref="LinkOptions.Client"/>.</summary>
    public static void Bind(IConfigurationSection section, GatewayOptions options)
    {
        ArgumentNullException.ThrowIfNull(section);
        ArgumentNullException.ThrowIfNull(options);
        ConfigurationSchema.Bind(section, options);

        // A link whose keys are all its client's (Tcp, Serial…) binds no worker key, and the binder would leave it out:
        // it is a link all the same, and the check says what it lacks rather than that there is none.
        foreach (IConfigurationSection link in section.GetSection(nameof(GatewayOptions.Links)).GetChildren())
        {
            options.Links.TryAdd(link.Key, new LinkOptions());
        }

        foreach ((string name, LinkOptions link) in options.Links)
        {
            link.Client.Read(ClientKeys(section.GetSection($"Links:{name}")));
            TagFiles.AddGroups(link);
        }
    }

    /// <summary>The keys of a link's section that are its client's, relative to the section (<c>Serial:BaudRate</c>).</summary>
    internal static IEnumerable<KeyValuePair<string, string?>> ClientKeys(IConfigurationSection link)
        => link.GetChildren()
            .Where(c => !ConfigurationSchema.IsSetting(typeof(LinkOptions), c.Key))
            .SelectMany(c => c.AsEnumerable())
            .Select(p => new KeyValuePair<string, string?>(p.Key.Substring(link.Path.Length + 1), p.Value));
}
