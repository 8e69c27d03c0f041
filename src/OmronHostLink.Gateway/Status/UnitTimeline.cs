using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// What the Lines view says about states over time, an output of its own: each link's and unit's state since when,
/// the last error of a unit in words (its outage's reason, or a group's read that failed while it answered), and the
/// unit's last few changes of state, so that a technician sees what happened (online → comm-error → demoted) and
/// when.
/// </summary>
/// <param name="time">The clock of the times recorded.</param>
internal sealed class UnitTimeline(TimeProvider time) : ITagOutput
{
    /// <summary>How many changes of state a unit keeps.</summary>
    public const int EventsKept = 10;

    private readonly object _gate = new();
    private readonly Dictionary<(string Link, int Unit), UnitRecord> _units = new();
    private readonly Dictionary<string, LinkRecord> _links = new(StringComparer.Ordinal);

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client)
    {
        ArgumentNullException.ThrowIfNull(client);
        lock (_gate)
        {
            LinkOf(link).Set(LinkState.Online, null, time.GetUtcNow());
        }
    }

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        lock (_gate)
        {
            LinkOf(link).Set(state, detail, time.GetUtcNow());
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
        ArgumentNullException.ThrowIfNull(change);
        if (change.Error is null)
        {
            return;
        }

        lock (_gate)
        {
            UnitRecord unit = UnitOf(change.Link, change.Unit);
            unit.LastError = $"{change.Tag}: {change.Error}";
            unit.LastErrorTime = change.Time;
        }
    }

    /// <inheritdoc/>
    public void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
        DateTimeOffset now = time.GetUtcNow();
        lock (_gate)
        {
            UnitRecord record = UnitOf(link, unit);
            if (record.State == state && record.Events.Count > 0)
            {
                return;
            }

            record.State = state;
            record.Since = now;
            if (detail is not null)
            {
                record.LastError = detail;
                record.LastErrorTime = now;
            }

            record.Events.Add(new UnitEventView { Time = now, State = state.Name(), Detail = detail });
            if (record.Events.Count > EventsKept)
            {
                record.Events.RemoveAt(0);
            }
        }
    }

    /// <summary>A link's state, since when and why; null before the link was heard of.</summary>
    public (LinkState State, DateTimeOffset Since, string? Detail)? Link(string link)
    {
        lock (_gate)
        {
            return _links.TryGetValue(link, out LinkRecord? r) && r.Since is { } since ? (r.State, since, r.Detail) : null;
        }
    }

    /// <summary>A unit's state since when (null: online since the link opened), its last error and its changes of state.</summary>
    public (UnitState State, DateTimeOffset? Since, string? LastError, DateTimeOffset? LastErrorTime, UnitEventView[] Events) Unit(string link, int unit)
    {
        lock (_gate)
        {
            if (!_units.TryGetValue((link, unit), out UnitRecord? r))
            {
                return (UnitState.Online, _links.GetValueOrDefault(link)?.Opened, null, null, []);
            }

            return (r.State, r.Since ?? _links.GetValueOrDefault(link)?.Opened, r.LastError, r.LastErrorTime, r.Events.ToArray());
        }
    }

    private LinkRecord LinkOf(string link)
    {
        if (!_links.TryGetValue(link, out LinkRecord? record))
        {
            record = new LinkRecord();
            _links.Add(link, record);
        }

        return record;
    }

    private UnitRecord UnitOf(string link, int unit)
    {
        if (!_units.TryGetValue((link, unit), out UnitRecord? record))
        {
            record = new UnitRecord();
            _units.Add((link, unit), record);
        }

        return record;
    }

    private sealed class LinkRecord
    {
        public LinkState State { get; private set; } = LinkState.Offline;

        public DateTimeOffset? Since { get; private set; }

        public DateTimeOffset? Opened { get; private set; }

        public string? Detail { get; private set; }

        public void Set(LinkState state, string? detail, DateTimeOffset now)
        {
            if (state == LinkState.Online && State == LinkState.Offline)
            {
                Opened = now;
            }

            if (state != State || Since is null)
            {
                Since = now;
            }

            State = state;
            Detail = detail;
        }
    }

    private sealed class UnitRecord
    {
        public UnitState State { get; set; }

        public DateTimeOffset? Since { get; set; }

        public string? LastError { get; set; }

        public DateTimeOffset? LastErrorTime { get; set; }

        public List<UnitEventView> Events { get; } = [];
    }
}
