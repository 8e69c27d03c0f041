using System.Threading.Channels;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The bounded, in-order queue between the tag sink and the one publisher loop. Adding never blocks: when the queue is
/// full the oldest message is dropped and counted. The publisher peeks at the head and removes it only once the broker
/// has acknowledged it, so a message in flight when the connection drops is sent again (at least once).
/// </summary>
public sealed class OutboundQueue
{
    private readonly Queue<OutboundMessage> _messages = new();
    private readonly Dictionary<string, int> _pendingByTopic = new(StringComparer.Ordinal);
    private readonly Channel<bool> _wake = Channel.CreateBounded<bool>(new BoundedChannelOptions(1) { FullMode = BoundedChannelFullMode.DropWrite });
    private long _sequence;
    private long _dropped;
    private long _episodeDropped;

    /// <summary>Creates a queue holding at most <paramref name="capacity"/> messages.</summary>
    public OutboundQueue(int capacity)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 1);
        Capacity = capacity;
    }

    /// <summary>Called (outside the queue's lock) with the number dropped each time the oldest messages are dropped.</summary>
    public event Action<long>? Dropped;

    /// <summary>Called (outside the queue's lock) when the first message of an overflow episode is dropped.</summary>
    public event Action? OverflowStarted;

    /// <summary>The most messages held.</summary>
    public int Capacity { get; }

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
        bool dropped = false;
        lock (_messages)
        {
            if (_messages.Count >= Capacity)
            {
                Forget(_messages.Dequeue());
                dropped = true;
                started = _episodeDropped == 0;
                _episodeDropped++;
                _dropped++;
            }

            message.Sequence = ++_sequence;
            _messages.Enqueue(message);
            _pendingByTopic[message.Topic] = _pendingByTopic.GetValueOrDefault(message.Topic) + 1;
        }

        if (started)
        {
            OverflowStarted?.Invoke();
        }

        if (dropped)
        {
            Dropped?.Invoke(1);
        }

        _wake.Writer.TryWrite(true);
    }

    /// <summary>The oldest message, left in the queue.</summary>
    public bool TryPeek(out OutboundMessage message)
    {
        lock (_messages)
        {
            return _messages.TryPeek(out message!);
        }
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

    private long EndEpisode()
    {
        long n = _episodeDropped;
        _episodeDropped = 0;
        return n;
    }

    private void Forget(OutboundMessage message)
    {
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
