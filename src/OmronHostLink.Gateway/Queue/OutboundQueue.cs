using System.Threading.Channels;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// The bounded, in-order queue between the tag sink and the one publisher loop. Adding never blocks: when the queue is
/// full the oldest message is dropped and counted. The publisher peeks at the head and removes it only once the broker
/// has acknowledged it, so a message in flight when the connection drops is sent again (at least once). With a
/// journal, every message taken and let go is also recorded outside the process (<see cref="IOutboundJournal"/>), and
/// what a previous run left is queued first; a size and an age then bound the queue as well as the count.
/// </summary>
internal sealed class OutboundQueue
{
    private readonly Queue<OutboundMessage> _messages = new();
    private readonly Dictionary<string, int> _pendingByTopic = new(StringComparer.Ordinal);
    private readonly Channel<bool> _wake = Channel.CreateBounded<bool>(new BoundedChannelOptions(1) { FullMode = BoundedChannelFullMode.DropWrite });
    private readonly IOutboundJournal? _journal;
    private readonly TimeProvider _time;
    private long _sequence;
    private long _dropped;
    private long _episodeDropped;
    private long _bytes;

    /// <summary>Creates a queue holding at most <paramref name="capacity"/> messages, in memory only.</summary>
    public OutboundQueue(int capacity)
        : this(capacity, null, long.MaxValue, null, TimeProvider.System)
    {
    }

    /// <summary>
    /// Creates a queue holding at most <paramref name="capacity"/> messages and <paramref name="maxBytes"/> bytes of
    /// them, none older than <paramref name="maxAge"/>, recorded in <paramref name="journal"/>; the messages the journal
    /// holds from a previous run are queued first, in their order.
    /// </summary>
    public OutboundQueue(int capacity, IOutboundJournal? journal, long maxBytes, TimeSpan? maxAge, TimeProvider timeProvider)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(maxBytes, 1);
        ArgumentNullException.ThrowIfNull(timeProvider);
        Capacity = capacity;
        MaxBytes = maxBytes;
        MaxAge = maxAge;
        _time = timeProvider;
        if (journal is null)
        {
            return;
        }

        foreach (OutboundMessage message in journal.Load())
        {
            _messages.Enqueue(message);
            _pendingByTopic[message.Topic] = _pendingByTopic.GetValueOrDefault(message.Topic) + 1;
            _bytes += message.Size;
            _sequence = Math.Max(_sequence, message.Sequence);
        }

        _journal = journal;
        Restored = _messages.Count;
        while (_messages.Count > Capacity || _bytes > MaxBytes)
        {
            Forget(_messages.Dequeue());
            RestoredDropped++;
            _dropped++;
        }

        RestoredExpired = (int)Expire();
        Restored -= RestoredDropped + RestoredExpired;
    }

    /// <summary>Called (outside the queue's lock) with the number dropped each time the oldest messages are dropped.</summary>
    public event Action<long>? Dropped;

    /// <summary>Called (outside the queue's lock) when the first message of an overflow episode is dropped.</summary>
    public event Action? OverflowStarted;

    /// <summary>Called (outside the queue's lock) with the number of messages dropped for being older than <see cref="MaxAge"/>.</summary>
    public event Action<long>? Expired;

    /// <summary>The most messages held.</summary>
    public int Capacity { get; }

    /// <summary>The most bytes of messages held (<see cref="OutboundMessage.Size"/>); beyond it the oldest are dropped.</summary>
    public long MaxBytes { get; }

    /// <summary>How long a message may wait; older ones are dropped. Null: as long as it takes.</summary>
    public TimeSpan? MaxAge { get; }

    /// <summary>How many messages the journal held from a previous run and the queue kept.</summary>
    public int Restored { get; }

    /// <summary>How many of the journal's messages did not fit (count or size) and were dropped, the oldest first.</summary>
    public int RestoredDropped { get; }

    /// <summary>How many of the journal's messages were older than <see cref="MaxAge"/> and were dropped.</summary>
    public int RestoredExpired { get; }

    /// <summary>Messages waiting, the one in flight included.</summary>
    public int Count
    {
        get
        {
            lock (_messages)
            {
                return _messages.Count;
            }
        }
    }

    /// <summary>All messages dropped since the queue was made.</summary>
    public long TotalDropped => Interlocked.Read(ref _dropped);

    /// <summary>Adds a message at the tail, dropping the oldest when full. Never blocks.</summary>
    public void Enqueue(OutboundMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        bool started = false;
        long dropped = 0;
        long expired;
        lock (_messages)
        {
            expired = Expire();
            while (_messages.Count > 0 && (_messages.Count >= Capacity || _bytes + message.Size > MaxBytes))
            {
                Forget(_messages.Dequeue());
                started |= _episodeDropped == 0;
                dropped++;
                _episodeDropped++;
                _dropped++;
            }

            message.Sequence = ++_sequence;
            message.QueuedAt = _time.GetUtcNow();
            _messages.Enqueue(message);
            _pendingByTopic[message.Topic] = _pendingByTopic.GetValueOrDefault(message.Topic) + 1;
            _bytes += message.Size;
            _journal?.Added(message);
        }

        if (started)
        {
            OverflowStarted?.Invoke();
        }

        if (dropped > 0)
        {
            Dropped?.Invoke(dropped);
        }

        RaiseExpired(expired);

        _wake.Writer.TryWrite(true);
    }

    /// <summary>The oldest message, left in the queue.</summary>
    public bool TryPeek(out OutboundMessage message)
    {
        long expired;
        bool found;
        lock (_messages)
        {
            expired = Expire();
            found = _messages.TryPeek(out message!);
        }

        RaiseExpired(expired);
        return found;
    }

    /// <summary>
    /// Removes <paramref name="message"/> after the broker took it, if it is still at the head (an overflow may have
    /// dropped it meanwhile).
    /// </summary>
    /// <returns>
    /// When the queue is now empty and messages were dropped since it last was: how many (the overflow episode is
    /// over); otherwise 0.
    /// </returns>
    public long Remove(OutboundMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        lock (_messages)
        {
            if (_messages.TryPeek(out OutboundMessage? head) && head.Sequence == message.Sequence)
            {
                Forget(_messages.Dequeue());
            }

            return _messages.Count == 0 ? EndEpisode() : 0;
        }
    }

    /// <summary>Ends the current overflow episode (at shutdown): how many were dropped in it, or 0.</summary>
    public long EndOverflowEpisode()
    {
        lock (_messages)
        {
            return EndEpisode();
        }
    }

    /// <summary>Whether a message for <paramref name="topic"/> waits (in flight included).</summary>
    public bool HasPending(string topic)
    {
        lock (_messages)
        {
            return _pendingByTopic.ContainsKey(topic);
        }
    }

    /// <summary>Waits until a message is queued or <see cref="Wake"/> is called; returns at once if one is already waiting.</summary>
    public async ValueTask WaitAsync(CancellationToken cancellationToken)
    {
        if (Count > 0)
        {
            return;
        }

        await _wake.Reader.ReadAsync(cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Wakes a <see cref="WaitAsync"/> (the connection dropped, the worker stops).</summary>
    public void Wake() => _wake.Writer.TryWrite(true);

    /// <summary>Drops the messages older than <see cref="MaxAge"/> from the head (under the lock); how many.</summary>
    private long Expire()
    {
        if (MaxAge is not { } maxAge)
        {
            return 0;
        }

        DateTimeOffset oldest = _time.GetUtcNow() - maxAge;
        long expired = 0;
        while (_messages.TryPeek(out OutboundMessage? head) && head.QueuedAt < oldest)
        {
            Forget(_messages.Dequeue());
            expired++;
            _dropped++;
        }

        return expired;
    }

    private void RaiseExpired(long expired)
    {
        if (expired > 0)
        {
            Dropped?.Invoke(expired);
            Expired?.Invoke(expired);
        }
    }

    private long EndEpisode()
    {
        long n = _episodeDropped;
        _episodeDropped = 0;
        return n;
    }

    private void Forget(OutboundMessage message)
    {
        _bytes -= message.Size;
        _journal?.Removed(message);
        int left = _pendingByTopic[message.Topic] - 1;
        if (left == 0)
        {
            _pendingByTopic.Remove(message.Topic);
        }
        else
        {
            _pendingByTopic[message.Topic] = left;
        }
    }
}
