using System.Collections.Concurrent;

namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// The clients of the links being polled, for outputs that write (MQTT commands, Sparkplug B DCMD): a write goes
/// through the client its link polls with, the link's one owner of the wire, and only while the link is polled.
/// </summary>
internal sealed class OpenLinks : ITagOutput
{
    private readonly ConcurrentDictionary<string, HostLinkUnit> _clients = new(StringComparer.Ordinal);

    /// <summary>The client of an open link; null when the link is not polled (stopping, or it could not be set up).</summary>
    public HostLinkUnit? ClientOf(string link) => _clients.TryGetValue(link, out HostLinkUnit? client) ? client : null;

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
        ArgumentNullException.ThrowIfNull(client);
        _clients[link] = client;
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        if (state == LinkState.Offline)
        {
            _clients.TryRemove(link, out _);
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
    }
}
