using Microsoft.Data.Sqlite;
using Microsoft.Extensions.Logging;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// The durable outage queue: every queued message is a row of a SQLite database until the broker has acknowledged it
/// (or the queue drops it), so a gateway that is killed, or stopped while the broker is away, sends them on its next run,
/// in their order. Write-ahead logging with <c>synchronous=NORMAL</c>: each change is in the operating system's hands
/// when the call returns, so it survives the process (SIGKILL, a crash); a power cut may cost the last changes, never the
/// database. The file is held exclusively: a second gateway cannot share it. A message the database cannot take (a full
/// disk) is held in memory and counted as at risk until it is written after all (once there is room again) or leaves
/// the queue, so a run that ends meanwhile leaves its loss to be announced.
/// </summary>
internal sealed class SqliteOutboundJournal : IOutboundJournal, IDisposable
{
    private readonly object _gate = new();
    private readonly SqliteConnection _connection;
    private readonly SqliteCommand _insert;
    private readonly SqliteCommand _delete;
    private readonly ILogger _logger;
    private readonly IOutboundJournal? _atRisk;
    private readonly SortedDictionary<long, OutboundMessage> _memoryOnly = [];
    private bool _failing;
    private bool _disposed;

    private SqliteOutboundJournal(string path, SqliteConnection connection, ILogger logger, IOutboundJournal? atRisk)
    {
        Path = path;
        _connection = connection;
        _logger = logger;
        _atRisk = atRisk;
        _insert = Command("INSERT INTO queue (seq, queued, topic, payload, retain, correlation) VALUES ($seq, $queued, $topic, $payload, $retain, $correlation)");
        foreach (string name in new[] { "$seq", "$queued", "$topic", "$payload", "$retain", "$correlation" })
        {
            _insert.Parameters.Add(new SqliteParameter { ParameterName = name });
        }

        _delete = Command("DELETE FROM queue WHERE seq = $seq");
        _delete.Parameters.Add(new SqliteParameter { ParameterName = "$seq" });
    }

    /// <summary>The database file.</summary>
    public string Path { get; }

    /// <summary>Opens (or creates) the database at <paramref name="path"/> and takes it for this process.</summary>
    /// <param name="path">The database file.</param>
    /// <param name="logger">Where a database that cannot be written is reported.</param>
    /// <param name="atRisk">Told of each message held in memory only while the database cannot take it (the count of unsent messages, <see cref="UnsentRecord"/>).</param>
    /// <param name="maxDatabaseBytes">
    /// The most the database may grow to: a write beyond it fails as on a full disk. The queue's own size bound
    /// (<c>Mqtt:DurableQueue:MaxMegabytes</c>) drops the oldest messages long before; null for no limit.
    /// </param>
    /// <exception cref="SqliteException">It cannot be opened or created, is no queue database, or another process holds it.</exception>
    public static SqliteOutboundJournal Open(string path, ILogger logger, IOutboundJournal? atRisk = null, long? maxDatabaseBytes = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        var connection = new SqliteConnection(new SqliteConnectionStringBuilder { DataSource = path, Mode = SqliteOpenMode.ReadWriteCreate, Pooling = false, DefaultTimeout = 2 }.ToString());
        try
        {
            connection.Open();
            Execute(connection, "PRAGMA locking_mode = EXCLUSIVE");
            Execute(connection, "PRAGMA journal_mode = WAL");
            Execute(connection, "PRAGMA synchronous = NORMAL");
            // The exclusive lock is taken by the first write: one now, so a second gateway fails here, not later.
            Execute(connection, "CREATE TABLE IF NOT EXISTS queue (seq INTEGER PRIMARY KEY, queued INTEGER NOT NULL, topic TEXT NOT NULL, payload BLOB NOT NULL, retain INTEGER NOT NULL, correlation BLOB)");
            Execute(connection, "BEGIN IMMEDIATE; COMMIT");
            if (maxDatabaseBytes is { } limit)
            {
                using SqliteCommand pageSize = connection.CreateCommand();
                pageSize.CommandText = "PRAGMA page_size";
                long pages = Math.Max(1, limit / Convert.ToInt64(pageSize.ExecuteScalar(), System.Globalization.CultureInfo.InvariantCulture));
                Execute(connection, $"PRAGMA max_page_count = {pages.ToString(System.Globalization.CultureInfo.InvariantCulture)}");
            }

            return new SqliteOutboundJournal(path, connection, logger, atRisk);
        }
        catch
        {
            connection.Dispose();
            throw;
        }
    }

    /// <summary>Why the database at <paramref name="path"/> cannot be the queue, in a few words; null when it can.</summary>
    public static string? Problem(string path)
    {
        try
        {
            System.IO.Directory.CreateDirectory(System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path))!);
            using SqliteOutboundJournal journal = Open(path, Microsoft.Extensions.Logging.Abstractions.NullLogger.Instance);
            return null;
        }
        catch (SqliteException e) when (e.SqliteErrorCode is 5 or 6)
        {
            return "another process holds it (a second gateway with the same Mqtt:ClientId and Mqtt:StateDirectory?)";
        }
        catch (SqliteException e)
        {
            return e.Message.Replace("SQLite Error ", "SQLite error ", StringComparison.Ordinal);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return e.Message;
        }
    }

    /// <inheritdoc/>
    public IReadOnlyList<OutboundMessage> Load()
    {
        lock (_gate)
        {
            var messages = new List<OutboundMessage>();
            using SqliteCommand select = Command("SELECT seq, queued, topic, payload, retain, correlation FROM queue ORDER BY seq");
            using SqliteDataReader reader = select.ExecuteReader();
            while (reader.Read())
            {
                messages.Add(new OutboundMessage(reader.GetString(2), (byte[])reader.GetValue(3), reader.GetInt64(4) != 0, reader.IsDBNull(5) ? null : (byte[])reader.GetValue(5))
                {
                    Sequence = reader.GetInt64(0),
                    QueuedAt = DateTimeOffset.FromUnixTimeMilliseconds(reader.GetInt64(1)),
                });
            }

            return messages;
        }
    }

    /// <summary>Messages held in memory only, because the database could not take them: counted as at risk.</summary>
    public int MemoryOnly
    {
        get
        {
            lock (_gate)
            {
                return _memoryOnly.Count;
            }
        }
    }

    /// <summary>Whether <paramref name="message"/> is in the database (not held in memory only).</summary>
    public bool Holds(OutboundMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        lock (_gate)
        {
            return !_disposed && !_memoryOnly.ContainsKey(message.Sequence);
        }
    }

    /// <inheritdoc/>
    public void Added(OutboundMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            StoreMemoryOnly();
            if (!Insert(message))
            {
                _memoryOnly.Add(message.Sequence, message);
                _atRisk?.Added(message);
            }
        }
    }

    /// <inheritdoc/>
    public void Removed(OutboundMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            if (_memoryOnly.Remove(message.Sequence))
            {
                _atRisk?.Removed(message);
                return;
            }

            _delete.Parameters[0].Value = message.Sequence;
            if (Run(_delete, message))
            {
                // A delete frees room: what waits in memory goes into the database now, not only with the next message.
                StoreMemoryOnly();
            }
        }
    }

    /// <summary>Closes the database; later calls are ignored.</summary>
    public void Dispose()
    {
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            _disposed = true;
            _insert.Dispose();
            _delete.Dispose();
            _connection.Dispose();
        }
    }

    /// <summary>Writes the messages held in memory into the database, oldest first, as far as it takes them.</summary>
    private void StoreMemoryOnly()
    {
        while (_memoryOnly.Count > 0)
        {
            OutboundMessage oldest = _memoryOnly.First().Value;
            if (!Insert(oldest))
            {
                return;
            }

            _memoryOnly.Remove(oldest.Sequence);
            _atRisk?.Removed(oldest);
        }
    }

    private bool Insert(OutboundMessage message)
    {
        _insert.Parameters[0].Value = message.Sequence;
        _insert.Parameters[1].Value = message.QueuedAt.ToUnixTimeMilliseconds();
        _insert.Parameters[2].Value = message.Topic;
        _insert.Parameters[3].Value = message.Payload;
        _insert.Parameters[4].Value = message.Retain ? 1 : 0;
        _insert.Parameters[5].Value = (object?)message.CorrelationData ?? DBNull.Value;
        return Run(_insert, message);
    }

    private bool Run(SqliteCommand command, OutboundMessage message)
    {
        try
        {
            command.ExecuteNonQuery();
            if (_failing)
            {
                _failing = false;
                QueueStoreLog.JournalWritable(_logger, Path);
            }

            return true;
        }
        catch (SqliteException e)
        {
            // A full disk or a removed file: the queue goes on in memory; only durability is lost meanwhile.
            if (!_failing)
            {
                _failing = true;
                QueueStoreLog.JournalFailed(_logger, Path, message.Topic, e.Message);
            }

            return false;
        }
    }

    private SqliteCommand Command(string text)
    {
        SqliteCommand command = _connection.CreateCommand();
        command.CommandText = text;
        return command;
    }

    private static void Execute(SqliteConnection connection, string text)
    {
        using SqliteCommand command = connection.CreateCommand();
        command.CommandText = text;
        command.ExecuteNonQuery();
    }
}
