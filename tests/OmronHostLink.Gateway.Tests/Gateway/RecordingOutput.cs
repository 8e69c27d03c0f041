namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>An output that records what the polling reports: tag outcomes and unit states, in order.</summary>
public sealed class RecordingOutput : ITagOutput
{
    private readonly List<object> _events = new();

    /// <summary>Everything reported so far: <see cref="TagChange"/>s and <see cref="UnitReport"/>s.</summary>
    public IReadOnlyList<object> Events
    {
        get
        {
            lock (_events)
            {
                return _events.ToArray();
            }
        }
    }

    /// <summary>The unit states reported so far.</summary>
    public IReadOnlyList<UnitReport> Units => Events.OfType<UnitReport>().ToArray();

    /// <summary>The tag outcomes reported so far.</summary>
    public IReadOnlyList<TagChange> Tags => Events.OfType<TagChange>().ToArray();

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
        lock (_events)
        {
            _events.Add(change);
        }
    }

    /// <inheritdoc/>
    public void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
        lock (_events)
        {
            _events.Add(new UnitReport(link, unit, state, detail));
        }
    }
}

/// <summary>A unit state as an output was told it.</summary>
public sealed record UnitReport(string Link, int Unit, UnitState State, string? Detail);
