using System.IO.MemoryMappedFiles;

namespace OmronHostLink.Gateway.Queue;

/// <summary>
/// How many queued messages the broker has not acknowledged, kept in a small memory-mapped file: each change is one
/// store to memory the operating system owns, so the count outlives the process (SIGKILL, a crash) at no cost to the
/// queue. The next run reads it and announces how many changes may have been lost (<see cref="PreviousLoss"/>); that
/// count stays recorded until the announcement itself is acknowledged. A power cut may cost the last changes of the
/// count. As the queue's journal it stands for a queue kept in memory only (no durable queue); beside a durable queue it
/// counts the messages the database could not take.
/// </summary>
internal sealed class UnsentRecord : IOutboundJournal, IDisposable
{
    /// <summary>"OHLUNSN1" read as a little-endian number: a file this class wrote.</summary>
    private const long Magic = 0x314E534E554C484F;
    private const int MagicAt = 0;
    private const int PendingAt = 8;
    private const int UnannouncedAt = 16;
    private const int Length = 24;

    private readonly object _gate = new();
    private readonly MemoryMappedFile _file;
    private readonly MemoryMappedViewAccessor _view;
    private long _pending;
    private long _unannounced;
    private OutboundMessage? _report;
    private bool _disposed;

    private UnsentRecord(string path, MemoryMappedFile file, MemoryMappedViewAccessor view)
    {
        Path = path;
        _file = file;
        _view = view;
        if (view.ReadInt64(MagicAt) == Magic)
        {
            PreviousLoss = Math.Max(0, view.ReadInt64(PendingAt)) + Math.Max(0, view.ReadInt64(UnannouncedAt));
        }

        // Until announced, what the last run left stays recorded; this run's queue starts empty.
        _unannounced = PreviousLoss;
        view.Write(PendingAt, 0L);
        view.Write(UnannouncedAt, _unannounced);
        view.Write(MagicAt, Magic);
    }

    /// <summary>The file.</summary>
    public string Path { get; }

    /// <summary>Messages the previous runs queued and may not have delivered: what their queues held when they ended, and what they could not announce.</summary>
    public long PreviousLoss { get; }

    /// <summary>Messages queued now and not yet acknowledged (the announcement excepted).</summary>
    public long Pending
    {
        get
        {
            lock (_gate)
            {
                return _pending;
            }
        }
    }

    /// <summary>Opens (or creates) the record at <paramref name="path"/> and holds it for this process.</summary>
    /// <exception cref="IOException">It cannot be created or opened, or another process holds it.</exception>
    /// <exception cref="UnauthorizedAccessException">The directory or the file may not be written.</exception>
    public static UnsentRecord Open(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        Directory.CreateDirectory(System.IO.Path.GetDirectoryName(System.IO.Path.GetFullPath(path))!);
        var stream = new FileStream(path, FileMode.OpenOrCreate, FileAccess.ReadWrite, FileShare.None);
        try
        {
            if (stream.Length != Length)
            {
                // New, or not one of ours: start from nothing.
                stream.SetLength(0);
                stream.SetLength(Length);
            }

            MemoryMappedFile file = MemoryMappedFile.CreateFromFile(stream, null, Length, MemoryMappedFileAccess.ReadWrite, HandleInheritability.None, leaveOpen: false);
            try
            {
                return new UnsentRecord(path, file, file.CreateViewAccessor(0, Length));
            }
            catch
            {
                file.Dispose();
                throw;
            }
        }
        catch
        {
            stream.Dispose();
            throw;
        }
    }

    /// <summary>
    /// <paramref name="report"/> announces <see cref="PreviousLoss"/>: it is not counted as pending, and once the broker
    /// has it (its removal from the queue) the previous loss is no longer recorded.
    /// </summary>
    public void Announcing(OutboundMessage report)
    {
        lock (_gate)
        {
            _report = report;
        }
    }

    /// <summary>The previous loss is announced (queued durably): it is no longer recorded.</summary>
    public void Announced()
    {
        lock (_gate)
        {
            _unannounced = 0;
            Write(UnannouncedAt, 0);
        }
    }

    /// <inheritdoc/>
    public IReadOnlyList<OutboundMessage> Load() => [];

    /// <inheritdoc/>
    public void Added(OutboundMessage message)
    {
        lock (_gate)
        {
            if (!ReferenceEquals(message, _report))
            {
                Write(PendingAt, ++_pending);
            }
        }
    }

    /// <inheritdoc/>
    public void Removed(OutboundMessage message)
    {
        lock (_gate)
        {
            if (ReferenceEquals(message, _report))
            {
                _report = null;
                _unannounced = 0;
                Write(UnannouncedAt, 0);
            }
            else
            {
                Write(PendingAt, --_pending);
            }
        }
    }

    /// <summary>Unmaps and closes the file; the count stays in it.</summary>
    public void Dispose()
    {
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            _disposed = true;
            _view.Dispose();
            _file.Dispose();
        }
    }

    private void Write(int at, long value)
    {
        if (!_disposed)
        {
            _view.Write(at, value);
        }
    }
}
