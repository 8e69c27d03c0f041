using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// Store-and-forward for the edge node (<see cref="SparkplugOptions.StoreAndForward"/>): the changes of metrics made
/// while the node has no session, each with the time it was read, kept in the outage queue of the JSON output
/// (<see cref="OutboundQueue"/>, in memory or in its SQLite journal) — bounded by count, size and age, the oldest dropped,
/// counted and logged — and handed back, oldest first, to be published as history after the next births.
/// </summary>
/// <remarks>
/// <para>
/// QoS 0 messages are not acknowledged: what was published in the last moments of a connection that died without a word
/// may never have reached the broker, and the loss is noticed only up to <see cref="Window"/> later. So the live changes
/// published within that window are remembered (<see cref="Published"/>) and kept again if the connection is lost
/// (<see cref="ConnectionLost"/>): a host application may then receive one of them twice (live, then as history with the
/// same timestamp), never not at all. Stored changes published as history leave the store only once that window has
/// passed with the connection up (<see cref="Next"/> confirms them); a connection lost sooner sends them again.
/// </para>
/// <para>
/// A session ended on purpose (the primary host offline, the gateway stopping) takes the published changes as received.
/// Not thread-safe: the edge node calls it under its own lock.
/// </para>
/// </remarks>
internal sealed class SparkplugHistory : IDisposable
{
    /// <summary>How many stored changes may be published and not yet confirmed; beyond it the flush waits for the window.</summary>
    private const int MaxInFlight = 10_000;

    private readonly OutboundQueue? _store;
    private readonly SqliteOutboundJournal? _journal;
    private readonly UnsentRecord? _record;
    private readonly TimeProvider _time;
    private readonly ILogger _logger;
    private readonly SparkplugStoreOptions _options;
    private readonly Queue<(IReadOnlyList<OutboundMessage> Batch, long PublishedAt)> _inFlight = new();
    private readonly Queue<(string Device, SparkplugMetricValue Change, long PublishedAt)> _published = new();
    private long _lastInFlight;
    private int _inFlightCount;
    private long _discarded;
    private long _previousLoss;
    private long _sent;

    private SparkplugHistory(SparkplugStoreOptions options, OutboundQueue? store, SqliteOutboundJournal? journal, UnsentRecord? record, TimeSpan window, TimeProvider time, ILogger logger)
    {
        _options = options;
        _store = store;
        _journal = journal;
        _record = record;
        Window = window;
        _time = time;
        _logger = logger;
        if (store is not null)
        {
            store.OverflowStarted += () => SparkplugLog.StoreOverflowing(_logger, _options.Capacity, _options.MaxMegabytes);
            store.Expired += n => SparkplugLog.StoreExpired(_logger, n, _options.MaxAge);
        }

        if (record is { PreviousLoss: > 0 } previous)
        {
            _previousLoss = previous.PreviousLoss;
            SparkplugLog.StorePreviousLoss(_logger, _previousLoss);
        }
    }

    /// <summary>Whether changes are kept at all.</summary>
    public bool Enabled => _store is not null;

    /// <summary>How long a published change stays at risk: the longest a dead connection can go unnoticed.</summary>
    public TimeSpan Window { get; }

    /// <summary>Changes kept now, those published as history and not yet confirmed included.</summary>
    public int Count => _store?.Count ?? 0;

    /// <summary>
    /// Changes dropped since the gateway started: over the store's bounds, too old, of a metric no longer configured, or
    /// lost with a previous run that kept them in memory only.
    /// </summary>
    public long Dropped => (_store?.TotalDropped ?? 0) + _discarded + _previousLoss;

    /// <summary>Stored changes published as history since the gateway started.</summary>
    public long Sent => _sent;

    /// <summary>When the next published batch is due to be confirmed; null when none waits.</summary>
    public DateTimeOffset? NextConfirmation
        => _inFlight.TryPeek(out var first) ? _time.GetUtcNow() + (Window - _time.GetElapsedTime(first.PublishedAt)) : null;

    /// <summary>
    /// Opens the store of <paramref name="options"/>: in memory, or in <c>{StateDirectory}/{ClientId}.sparkplug.queue.db</c>
    /// with the changes a previous run left; always with the count of changes held in memory only
    /// (<c>{ClientId}.sparkplug.unsent</c>), so that a run that dies with some is announced by the next.
    /// </summary>
    public static SparkplugHistory Open(SparkplugOptions options, string contentRoot, TimeProvider time, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(options);
        SparkplugStoreOptions store = options.StoreAndForward ?? new SparkplugStoreOptions();
        TimeSpan window = options.KeepAlive * 1.5;
        if (!store.Enabled)
        {
            return new SparkplugHistory(store, null, null, null, window, time, logger);
        }

        string directory = OutboundQueueStore.StateDirectory(options.StateDirectory, contentRoot);
        string name = FileName(options.ClientIdOrDefault);
        UnsentRecord? record = null;
        try
        {
            record = UnsentRecord.Open(Path.Combine(directory, name + ".unsent"));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            SparkplugLog.StoreRecordUnavailable(logger, Path.Combine(directory, name + ".unsent"), e.Message);
        }

        long maxBytes = store.MaxMegabytes * 1024L * 1024L;
        if (!store.Durable)
        {
            var memory = new OutboundQueue(store.Capacity, record, maxBytes, store.MaxAge, time);
            return new SparkplugHistory(store, memory, null, record, window, time, logger);
        }

        SqliteOutboundJournal journal = SqliteOutboundJournal.Open(JournalPath(options, contentRoot), logger, atRisk: record, output: "Sparkplug");
        var durable = new OutboundQueue(store.Capacity, journal, maxBytes, store.MaxAge, time);
        SparkplugLog.StoreOpened(logger, journal.Path, durable.Restored);
        if (durable.RestoredDropped + durable.RestoredExpired > 0)
        {
            SparkplugLog.StoreRestoredDropped(logger, journal.Path, durable.RestoredDropped, durable.RestoredExpired);
        }

        return new SparkplugHistory(store, durable, journal, record, window, time, logger);
    }

    /// <summary>The durable store's database for <paramref name="options"/>.</summary>
    public static string JournalPath(SparkplugOptions options, string contentRoot)
    {
        ArgumentNullException.ThrowIfNull(options);
        return Path.Combine(OutboundQueueStore.StateDirectory(options.StateDirectory, contentRoot), FileName(options.ClientIdOrDefault) + ".queue.db");
    }

    /// <summary>Keeps a change made while it cannot be published live.</summary>
    public void Store(string device, SparkplugMetricValue change)
        => _store?.Enqueue(new OutboundMessage(device, SparkplugPayloads.StoredChange(change), Retain: false));

    /// <summary>Remembers live changes just published, for the window in which a lost connection may have swallowed them.</summary>
    public void Published(string device, IEnumerable<SparkplugMetricValue> changes)
    {
        if (_store is null)
        {
            return;
        }

        long now = _time.GetTimestamp();
        foreach (SparkplugMetricValue change in changes)
        {
            _published.Enqueue((device, change, now));
        }

        Forget();
    }

    /// <summary>
    /// The connection died: the live changes of the window are kept again, in the order they were published, and the
    /// stored changes published as history and not yet confirmed will be published again.
    /// </summary>
    public void ConnectionLost()
    {
        Forget();
        while (_published.TryDequeue(out var published))
        {
            Store(published.Device, published.Change);
        }

        _inFlight.Clear();
        _inFlightCount = 0;
        _lastInFlight = 0;
    }

    /// <summary>The session ended on purpose: what was published counts as received.</summary>
    public void SessionEnded()
    {
        _published.Clear();
        while (_inFlight.TryDequeue(out var batch))
        {
            Confirm(batch.Batch);
        }

        _inFlightCount = 0;
        _lastInFlight = 0;
    }

    /// <summary>
    /// The next stored changes to publish as history: up to <paramref name="max"/> of one device, in the order they were
    /// kept, after those published and not yet confirmed (confirming those whose window has passed first). Null when
    /// there are none, or too many wait for confirmation.
    /// </summary>
    public HistoryBatch? Next(int max)
    {
        if (_store is null)
        {
            return null;
        }

        while (_inFlight.TryPeek(out var first) && _time.GetElapsedTime(first.PublishedAt) >= Window)
        {
            _inFlight.Dequeue();
            _inFlightCount -= first.Batch.Count;
            Confirm(first.Batch);
        }

        if (_inFlightCount >= MaxInFlight)
        {
            return null;
        }

        IReadOnlyList<OutboundMessage> next = _store.PeekAfter(_lastInFlight, max);
        if (next.Count == 0)
        {
            return null;
        }

        // One device a message; a metric twice only with different timestamps (the specification's rule for data).
        string device = next[0].Topic;
        var batch = new List<OutboundMessage>();
        var changes = new List<Wire.Payload.Types.Metric?>();
        var seen = new HashSet<(string, ulong)>();
        foreach (OutboundMessage message in next)
        {
            if (message.Topic != device)
            {
                break;
            }

            Wire.Payload.Types.Metric? change = SparkplugPayloads.TryParseStoredChange(message.Payload);
            if (change is not null && !seen.Add((change.Name, change.Timestamp)))
            {
                break;
            }

            batch.Add(message);
            changes.Add(change);
        }

        return new HistoryBatch(device, batch, changes, AtHead: _inFlight.Count == 0);
    }

    /// <summary>The batch was published (or had nothing to publish): it leaves the store once the window has passed.</summary>
    public void MarkSent(HistoryBatch batch, int published)
    {
        ArgumentNullException.ThrowIfNull(batch);
        _inFlight.Enqueue((batch.Messages, _time.GetTimestamp()));
        _inFlightCount += batch.Messages.Count;
        _lastInFlight = batch.Messages[^1].Sequence;
        _sent += published;
    }

    /// <summary>
    /// A batch with nothing to publish (the births carry its changes): at the head of the store it leaves at once;
    /// behind changes published and not yet confirmed, with them.
    /// </summary>
    public void Skip(HistoryBatch batch)
    {
        ArgumentNullException.ThrowIfNull(batch);
        if (batch.AtHead)
        {
            Confirm(batch.Messages);
        }
        else
        {
            MarkSent(batch, 0);
        }
    }

    /// <summary>Changes of a batch that cannot be published (their metric is gone): counted as dropped.</summary>
    public void Discarded(int count) => _discarded += count;

    /// <summary>
    /// The batch's device is not born in this session (its unit does not answer): its changes go behind the others, so
    /// that those of the other devices can be published. Only for a batch at the head of the store.
    /// </summary>
    public void Postpone(HistoryBatch batch)
    {
        ArgumentNullException.ThrowIfNull(batch);
        for (int i = 0; i < batch.Messages.Count; i++)
        {
            _store?.MoveHeadToTail();
        }
    }

    /// <summary>A birth of a session was published: a previous run's loss, now in its figures, is announced.</summary>
    public void Announced() => _record?.Announced();

    /// <inheritdoc/>
    public void Dispose()
    {
        _journal?.Dispose();
        _record?.Dispose();
    }

    private void Confirm(IReadOnlyList<OutboundMessage> batch)
    {
        foreach (OutboundMessage message in batch)
        {
            long overflowed = _store!.Remove(message);
            if (overflowed > 0)
            {
                SparkplugLog.StoreOverflowed(_logger, overflowed, Dropped);
            }
        }
    }

    private void Forget()
    {
        while (_published.TryPeek(out var oldest) && _time.GetElapsedTime(oldest.PublishedAt) > Window)
        {
            _published.Dequeue();
        }
    }

    /// <summary>The client id as a file name on every system, marked as the Sparkplug output's.</summary>
    private static string FileName(string clientId)
        => new string(clientId.Select(c => c < ' ' || "\\/:*?\"<>|".Contains(c, StringComparison.Ordinal) ? '_' : c).ToArray()) + ".sparkplug";

    /// <summary>Stored changes to publish together.</summary>
    /// <param name="Device">Their device's id.</param>
    /// <param name="Messages">The store's messages, in order.</param>
    /// <param name="Changes">Each one read (null for one that cannot be read).</param>
    /// <param name="AtHead">Whether they are at the head of the store (nothing published waits before them).</param>
    internal sealed record HistoryBatch(string Device, IReadOnlyList<OutboundMessage> Messages, IReadOnlyList<Wire.Payload.Types.Metric?> Changes, bool AtHead);
}
