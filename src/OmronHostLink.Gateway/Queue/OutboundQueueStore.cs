using System.Text.Json;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Mqtt;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// What the outbound queue keeps outside the process, in <see cref="MqttOptions.StateDirectory"/>: the count of unsent
/// messages always (<c>{ClientId}.unsent</c>, <see cref="UnsentRecord"/>) and, with <c>Mqtt:DurableQueue:Enabled</c>, the
/// messages themselves (<c>{ClientId}.queue.db</c>, <see cref="SqliteOutboundJournal"/>; then the count holds only the
/// messages the database could not take). It makes the queue: the previous run's messages first, and an announcement
/// of what the previous run may have lost.
/// </summary>
public sealed class OutboundQueueStore : IDisposable
{
    private readonly UnsentRecord? _record;
    private readonly SqliteOutboundJournal? _journal;

    /// <summary>Opens the files for <paramref name="options"/>; a count that cannot be kept is logged, not fatal.</summary>
    /// <param name="options">The MQTT options (validated: a durable queue's database can be opened).</param>
    /// <param name="contentRoot">The host's content root, below which the default state directory lies.</param>
    /// <param name="logger">Where the queue's own events go.</param>
    public OutboundQueueStore(MqttOptions options, string contentRoot, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(options);
        Logger = logger;
        Directory = StateDirectory(options, contentRoot);
        string name = FileName(options.ClientIdOrDefault);
        string recordPath = Path.Combine(Directory, name + ".unsent");
        try
        {
            _record = UnsentRecord.Open(recordPath);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            QueueStoreLog.RecordUnavailable(logger, recordPath, e.Message);
        }

        if (options.DurableQueue.Enabled)
        {
            _journal = SqliteOutboundJournal.Open(JournalPath(options, contentRoot), logger, atRisk: _record);
        }
    }

    /// <summary>The state directory in effect.</summary>
    public string Directory { get; }

    private ILogger Logger { get; }

    /// <summary>
    /// The state directory for <paramref name="options"/>: <c>Mqtt:StateDirectory</c> (relative to the content root),
    /// else systemd's <c>STATE_DIRECTORY</c>, else <c>%ProgramData%\OmronHostLink.Gateway</c> on Windows, else
    /// <c>state</c> below the content root.
    /// </summary>
    public static string StateDirectory(MqttOptions options, string contentRoot)
    {
        ArgumentNullException.ThrowIfNull(options);
        if (!string.IsNullOrWhiteSpace(options.StateDirectory))
        {
            return Path.GetFullPath(options.StateDirectory, contentRoot);
        }

        // systemd passes the directories of StateDirectory= separated by ':'; the first is the service's own.
        if (Environment.GetEnvironmentVariable("STATE_DIRECTORY") is { Length: > 0 } systemd)
        {
            return systemd.Split(':')[0];
        }

        return OperatingSystem.IsWindows()
            ? Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.CommonApplicationData), GatewayHost.ServiceName)
            : Path.Combine(contentRoot, "state");
    }

    /// <summary>The durable queue's database for <paramref name="options"/>.</summary>
    public static string JournalPath(MqttOptions options, string contentRoot)
    {
        ArgumentNullException.ThrowIfNull(options);
        return Path.Combine(StateDirectory(options, contentRoot), FileName(options.ClientIdOrDefault) + ".queue.db");
    }

    /// <summary>
    /// The queue: bounded by <c>Mqtt:QueueCapacity</c>, and with the durable queue by its size and age too; what the
    /// previous run left comes first, then the announcement of what it may have lost (on <see cref="MqttTopics.WorkerLost"/>).
    /// </summary>
    public OutboundQueue CreateQueue(MqttOptions options, MqttTopics topics, TimeProvider timeProvider)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(topics);
        ArgumentNullException.ThrowIfNull(timeProvider);
        OutboundQueue queue;
        if (_journal is not null)
        {
            MqttDurableQueueOptions durable = options.DurableQueue;
            queue = new OutboundQueue(options.QueueCapacity, _journal, durable.MaxMegabytes * 1024L * 1024L, durable.MaxAge, timeProvider);
            QueueStoreLog.DurableQueueOpened(Logger, _journal.Path, queue.Restored);
            if (queue.RestoredDropped + queue.RestoredExpired > 0)
            {
                QueueStoreLog.RestoredDropped(Logger, _journal.Path, queue.RestoredDropped, queue.RestoredExpired);
            }

            queue.Expired += n => QueueStoreLog.Expired(Logger, n, durable.MaxAge);
        }
        else
        {
            queue = new OutboundQueue(options.QueueCapacity, _record, long.MaxValue, null, timeProvider);
        }

        if (_record is { PreviousLoss: > 0 } record)
        {
            var payload = new LostMessagesPayload { Lost = record.PreviousLoss, Time = timeProvider.GetUtcNow() };
            var report = new OutboundMessage(topics.WorkerLost, JsonSerializer.SerializeToUtf8Bytes(payload, MqttJson.Context.LostMessagesPayload), Retain: false);
            QueueStoreLog.PreviousLoss(Logger, record.PreviousLoss, topics.WorkerLost);
            record.Announcing(report);
            queue.Enqueue(report);
            if (_journal is not null && _journal.Holds(report))
            {
                // Now in the durable queue: it is sent even if this run ends first.
                record.Announced();
            }
        }

        return queue;
    }

    /// <summary>Closes the files; the count and the durable queue stay in them for the next run.</summary>
    public void Dispose()
    {
        _journal?.Dispose();
        _record?.Dispose();
    }

    /// <summary>The client id as a file name on every system (no <c>\ : * ? " &lt; &gt; |</c>).</summary>
    private static string FileName(string clientId)
        => new(clientId.Select(c => c < ' ' || "\\/:*?\"<>|".Contains(c, StringComparison.Ordinal) ? '_' : c).ToArray());
}
