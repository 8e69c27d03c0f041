using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The Tags view's store, an output of its own: every tag's last value, quality and error, the time it was last read,
/// and its recent numeric values for a sparkline. Each outcome takes a version number, so that a page is sent only
/// the tags that changed since its last update. Taking an outcome is a dictionary look-up and a few stores under the
/// tag's own lock: the polling never waits for a page.
/// </summary>
internal sealed class TagBoard : ITagOutput
{
    /// <summary>How many recent values a tag keeps for its sparkline.</summary>
    public const int HistoryLength = 60;

    private readonly Dictionary<(string Link, int Unit, string Name), Entry> _byName = new();
    private readonly Entry[] _entries;
    private readonly TimeSpan _historySpacing;
    private long _version;

    /// <summary>Lists every tag of the enabled links, in link, unit and name order.</summary>
    /// <param name="gateway">The validated <c>HostLink</c> section.</param>
    /// <param name="status">The <c>Status</c> section: a tag's history keeps one value per refresh interval at most.</param>
    public TagBoard(IOptions<GatewayOptions> gateway, IOptions<StatusOptions> status)
    {
        ArgumentNullException.ThrowIfNull(gateway);
        ArgumentNullException.ThrowIfNull(status);
        _historySpacing = status.Value.RefreshInterval;
        var entries = new List<Entry>();
        foreach ((string link, LinkOptions options) in gateway.Value.Links.Where(l => l.Value.Enabled).OrderBy(l => l.Key, StringComparer.Ordinal))
        {
            foreach ((string name, PollGroupOptions group) in options.Groups.OrderBy(g => g.Value.Unit).ThenBy(g => g.Key, StringComparer.Ordinal))
            {
                PollValueTypes.TryParse(group.Type, out PlcValueType type);
                var entry = new Entry(entries.Count, link, group.Unit, name, PlcAddress.Parse(group.Address).ToString(), type.Name(), group.Count, group.Interval);
                entries.Add(entry);
                _byName[(link, group.Unit, name)] = entry;
            }
        }

        _entries = entries.ToArray();
    }

    /// <summary>How many tags there are.</summary>
    public int Count => _entries.Length;

    /// <summary>The version of the latest outcome taken; 0 before any.</summary>
    public long Version => Interlocked.Read(ref _version);

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
        ArgumentNullException.ThrowIfNull(change);
        if (!_byName.TryGetValue((change.Link, change.Unit, change.Tag), out Entry? entry))
        {
            return;
        }

        lock (entry)
        {
            entry.Quality = change.Quality;
            entry.Time = change.Time;
            entry.Error = change.Error;
            if (change.Quality == TagQuality.Good)
            {
                entry.Value = change.Value;
                entry.ReadTime = change.Time;
                if (Numeric(change.Value) is { } number)
                {
                    entry.Remember(number, change.Time, _historySpacing);
                }
            }

            entry.Version = Interlocked.Increment(ref _version);
        }
    }

    /// <summary>Every tag as it stands, with its description and history.</summary>
    public List<TagRow> All()
    {
        var rows = new List<TagRow>(_entries.Length);
        foreach (Entry entry in _entries)
        {
            lock (entry)
            {
                rows.Add(entry.Row(full: true));
            }
        }

        return rows;
    }

    /// <summary>The tags whose outcome changed after <paramref name="version"/>: index, value, quality, times and error only.</summary>
    public List<TagRow> ChangedSince(long version)
    {
        var rows = new List<TagRow>();
        foreach (Entry entry in _entries)
        {
            if (Volatile.Read(ref entry.Version) <= version)
            {
                continue;
            }

            lock (entry)
            {
                rows.Add(entry.Row(full: false));
            }
        }

        return rows;
    }

    /// <summary>A value a sparkline can draw: a single number (a bool as 0 or 1); null for text and several values.</summary>
    internal static double? Numeric(object? value) => value switch
    {
        ushort v => v,
        short v => v,
        int v => v,
        uint v => v,
        float v when float.IsFinite(v) => v,
        double v when double.IsFinite(v) => v,
        bool v => v ? 1 : 0,
        _ => null,
    };

    /// <summary>One tag: its description, fixed, and its last outcome, under its own lock.</summary>
    private sealed class Entry(int index, string link, int unit, string name, string address, string type, int count, TimeSpan interval)
    {
        private readonly double[] _history = new double[HistoryLength];
        private int _historyStart;
        private int _historyCount;
        private DateTimeOffset _lastPoint;

        public long Version;

        public object? Value { get; set; }

        public TagQuality? Quality { get; set; }

        public DateTimeOffset? Time { get; set; }

        public DateTimeOffset? ReadTime { get; set; }

        public string? Error { get; set; }

        /// <summary>Keeps a value for the sparkline: one a spacing at most, the latest standing for its spacing.</summary>
        public void Remember(double value, DateTimeOffset time, TimeSpan spacing)
        {
            if (_historyCount > 0 && time - _lastPoint < spacing)
            {
                _history[(_historyStart + _historyCount - 1) % HistoryLength] = value;
                return;
            }

            _lastPoint = time;
            if (_historyCount < HistoryLength)
            {
                _history[(_historyStart + _historyCount++) % HistoryLength] = value;
            }
            else
            {
                _history[_historyStart] = value;
                _historyStart = (_historyStart + 1) % HistoryLength;
            }
        }

        public TagRow Row(bool full) => new()
        {
            Index = index,
            Link = full ? link : null,
            Unit = full ? unit : null,
            Name = full ? name : null,
            Address = full ? address : null,
            Type = full ? type : null,
            Count = full ? count : null,
            IntervalMs = full ? interval.TotalMilliseconds : null,
            History = full ? History() : null,
            Value = Value,
            Quality = Quality?.Name(),
            Time = Time,
            ReadTime = ReadTime,
            Error = Error,
        };

        private double[] History()
        {
            var values = new double[_historyCount];
            for (int i = 0; i < _historyCount; i++)
            {
                values[i] = _history[(_historyStart + i) % HistoryLength];
            }

            return values;
        }
    }
}
