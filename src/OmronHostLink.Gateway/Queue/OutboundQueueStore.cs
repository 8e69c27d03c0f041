using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// What the outbound queue keeps outside the process, in the state directory: the count of unsent messages always
/// (<c>{ClientId}.unsent</c>, <see cref="UnsentRecord"/>) and, with a durable queue, the messages themselves
/// (<c>{ClientId}.queue.db</c>, <see cref="SqliteOutboundJournal"/>; then the count holds only the messages the database
/// could not take). It makes the queue: the previous run's messages first, and an announcement of what the previous run
/// may have lost.
/// </summary>
internal sealed class OutboundQueueStore : IDisposable
{
    private readonly UnsentRecord? _record;
    private readonly SqliteOutboundJournal? _journal;
    private readonly DurableQueueOptions _durable;

    /// <summary>Opens the files in <paramref name="directory"/>; a count that cannot be kept is logged, not fatal.</summary>
    /// <param name="directory">The state directory (<see cref="StateDirectory"/>).</param>
    /// <param name="clientId">The client id the files are named after.</param>
    /// <param name="durable">The durable queue's options (validated: its database can be opened).</param>
    /// <param name="logger">Where the queue's own events go.</param>
    public OutboundQueueStore(string directory, string clientId, DurableQueueOptions durable, ILogger logger)
    {
        ArgumentNullException.ThrowIfNull(durable);
        Logger = logger;
        Directory = directory;
        _durable = durable;
        string recordPath = Path.Combine(Directory, FileName(clientId) + ".unsent");
        try
        {
            _record = UnsentRecord.Open(recordPath);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            QueueStoreLog.RecordUnavailable(logger, recordPath, e.Message);
        }

        if (durable.Enabled)
        {
            _journal = SqliteOutboundJournal.Open(JournalPath(directory, clientId), logger, atRisk: _record);
        }
    }

    /// <summary>The state directory in effect.</summary>
    public string Directory { get; }

    private ILogger Logger { get; }

    /// <summary>
    /// The state directory: <paramref name="configured"/> (<c>Mqtt:StateDirectory</c>, relative to the content root),
    /// else systemd's <c>STATE_DIRECTORY</c>, else <c>%ProgramData%\OmronHostLink.Gateway</c> on Windows, else
    /// <c>state</c> below the content root.
    /// </summary>
    public static string StateDirectory(string? configured, string contentRoot)
    {
        if (!string.IsNullOrWhiteSpace(configured))
        {
            return Path.GetFullPath(configured, contentRoot);
        }

        // systemd passes the directories of StateDirectory= separated by ':'; the first is the service's own.
        if (Environment.GetEnvironmentVariable("STATE_DIRECTORY") is { Length: > 0 } systemd)
        {
            return systemd.Split(':')[0];
        }

        return OperatingSystem.IsWindows()
            ? Path.Combine(Environment.GetFolderPath(Environment.SpecialFolder.CommonApplicationData), GatewayNames.Service)
            : Path.Combine(contentRoot, "state");
    }

    /// <summary>The durable queue's database in <paramref name="directory"/> for <paramref name="clientId"/>.</summary>
    public static string JournalPath(string directory, string clientId) => Path.Combine(directory, FileName(clientId) + ".queue.db");

    /// <summary>
    /// The queue: bounded by <paramref name="capacity"/> messages, and with the durable queue by its size and age too;
    /// what the previous run left comes first, then the announcement of what it may have lost.
    /// </summary>
    /// <param name="capacity">How many messages may wait (<c>Mqtt:QueueCapacity</c>).</param>
    /// <param name="timeProvider">The clock of the queue's ages.</param>
    /// <param name="lossReport">The message that announces how many messages the previous run may have lost.</param>
    public OutboundQueue CreateQueue(int capacity, TimeProvider timeProvider, Func<long, OutboundMessage> lossReport)
    {
        ArgumentNullException.ThrowIfNull(timeProvider);
        ArgumentNullException.ThrowIfNull(lossReport);
        OutboundQueue queue;
        if (_journal is not null)
        {
            DurableQueueOptions durable = _durable;
            queue = new OutboundQueue(capacity, _journal, durable.MaxMegabytes * 1024L * 1024L, durable.MaxAge, timeProvider);
            QueueStoreLog.DurableQueueOpened(Logger, _journal.Path, queue.Restored);
            if (queue.RestoredDropped + queue.RestoredExpired > 0)
            {
                QueueStoreLog.RestoredDropped(Logger, _journal.Path, queue.RestoredDropped, queue.RestoredExpired);
            }

            queue.Expired += n => QueueStoreLog.Expired(Logger, n, durable.MaxAge);
        }
        else
        {
            queue = new OutboundQueue(capacity, _record, long.MaxValue, null, timeProvider);
        }

        if (_record is { PreviousLoss: > 0 } record)
        {
            OutboundMessage report = lossReport(record.PreviousLoss);
            QueueStoreLog.PreviousLoss(Logger, record.PreviousLoss, report.Topic);
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
