namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>An output that records what the polling reports: tag outcomes, unit states, scan plans and cycles, in order.</summary>
internal sealed class RecordingOutput : ITagOutput, IScanOutput
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

    /// <summary>The scan classes' plans reported so far.</summary>
    public IReadOnlyList<ScanPlan> Plans => Events.OfType<ScanPlan>().ToArray();

    /// <summary>The scan classes' cycles reported so far.</summary>
    public IReadOnlyList<ScanCycle> Cycles => Events.OfType<ScanCycle>().ToArray();

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

    /// <inheritdoc/>
    public void ScanPlanned(ScanPlan plan)
    {
        lock (_events)
        {
            _events.Add(plan);
        }
    }

    /// <inheritdoc/>
    public void ScanCycled(ScanCycle cycle)
    {
        lock (_events)
        {
            _events.Add(cycle);
        }
    }
}

/// <summary>A unit state as an output was told it.</summary>
public sealed record UnitReport(string Link, int Unit, UnitState State, string? Detail);
