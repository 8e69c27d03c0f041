namespace OmronHostLink.Worker.Polling;

/// <summary>
/// Decides which poll group of a link runs next. The group whose due time is earliest goes first; on a tie, the one
/// that ran least recently. A group that has just run is due again after its interval, so any group already waiting
/// is ahead of it: none starves, however busy the link. Ticks missed while the link was busy are not queued up: the
/// next due time skips forward to the first one after now, keeping the group's phase. Pure: time is passed in.
/// </summary>
/// <typeparam name="T">The item scheduled (a poll group).</typeparam>
public sealed class PollScheduler<T>
{
    private readonly Entry[] _entries;
    private long _sequence;

    /// <summary>Creates the scheduler; every item is due at <paramref name="start"/>, in the order given.</summary>
    public PollScheduler(IEnumerable<(T Item, TimeSpan Interval)> items, TimeSpan start)
    {
        ArgumentNullException.ThrowIfNull(items);
        _entries = items.Select(i => new Entry(i.Item, i.Interval, start)).ToArray();
        if (_entries.Length == 0)
        {
            throw new ArgumentException("Nothing to schedule.", nameof(items));
        }

        foreach (Entry e in _entries)
        {
            if (e.Interval <= TimeSpan.Zero)
            {
                throw new ArgumentOutOfRangeException(nameof(items), e.Interval, "Every interval must be more than 0.");
            }

            // Earlier items win the first ties.
            e.LastRun = ++_sequence - _entries.Length - 1;
        }
    }

    /// <summary>The number of items.</summary>
    public int Count => _entries.Length;

    /// <summary>The item in <paramref name="slot"/>.</summary>
    public T this[int slot] => _entries[slot].Item;

    /// <summary>The due time of the item in <paramref name="slot"/>.</summary>
    public TimeSpan DueAt(int slot) => _entries[slot].Due;

    /// <summary>
    /// The slot to run next and when. <paramref name="notBefore"/> may hold an item back (its PLC is in backoff):
    /// the item's effective due time is the later of the two.
    /// </summary>
    public (int Slot, TimeSpan At) Next(Func<T, TimeSpan>? notBefore = null)
    {
        int best = -1;
        TimeSpan bestAt = TimeSpan.MaxValue;
        for (int i = 0; i < _entries.Length; i++)
        {
            Entry e = _entries[i];
            TimeSpan at = e.Due;
            if (notBefore is not null)
            {
                TimeSpan hold = notBefore(e.Item);
                if (hold > at)
                {
                    at = hold;
                }
            }

            if (best < 0 || at < bestAt || (at == bestAt && e.LastRun < _entries[best].LastRun))
            {
                best = i;
                bestAt = at;
            }
        }

        return (best, bestAt);
    }

    /// <summary>
    /// Records that the item in <paramref name="slot"/> ran (successfully or not) and finished at <paramref name="now"/>;
    /// sets its next due time to the first tick of its interval after now.
    /// </summary>
    /// <returns>The number of ticks skipped because they had already passed.</returns>
    public long Completed(int slot, TimeSpan now)
    {
        Entry e = _entries[slot];
        e.LastRun = ++_sequence;
        TimeSpan next = e.Due + e.Interval;
        if (next > now)
        {
            e.Due = next;
            return 0;
        }

        long behind = (now - e.Due).Ticks / e.Interval.Ticks;
        e.Due += TimeSpan.FromTicks(e.Interval.Ticks * (behind + 1));
        return behind;
    }

    private sealed class Entry(T item, TimeSpan interval, TimeSpan due)
    {
        public T Item { get; } = item;

        public TimeSpan Interval { get; } = interval;

        public TimeSpan Due { get; set; } = due;

        public long LastRun { get; set; }
    }
}
