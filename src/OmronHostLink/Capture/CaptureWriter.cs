namespace OmronHostLink.Capture;

/// <summary>
/// Writes frames to a capture file as they cross a line: a pcap for Wireshark (<see cref="CaptureFormat"/>) or JSON lines
/// for scripts, chosen by the file name. Safe for several writers at once (the two directions of a line); the file is
/// flushed within a second of each record and when the writer is disposed.
/// </summary>
internal abstract class CaptureWriter : IDisposable
{
    private static readonly TimeSpan FlushDelay = TimeSpan.FromSeconds(1);

    private readonly object _gate = new();
    private readonly Stream _file;
    private readonly Timer _flush;
    private bool _dirty;
    private bool _disposed;

    protected CaptureWriter(Stream file)
    {
        _file = file;
        using (ExecutionContext.SuppressFlow())
        {
            _flush = new Timer(static s => ((CaptureWriter)s!).FlushIfDirty(), this, Timeout.Infinite, Timeout.Infinite);
        }
    }

    /// <summary>The number of records written.</summary>
    public long Records { get; private set; }

    /// <summary>The file name endings that choose a format, for messages.</summary>
    public const string KnownEndings = ".pcap (Wireshark) or .jsonl (JSON lines)";

    /// <summary>Whether <paramref name="path"/> names a JSON lines file (<c>.jsonl</c>, <c>.ndjson</c>, <c>.json</c>) rather than a pcap.</summary>
    public static bool IsJsonLines(string path)
        => path.EndsWith(".jsonl", StringComparison.OrdinalIgnoreCase)
            || path.EndsWith(".ndjson", StringComparison.OrdinalIgnoreCase)
            || path.EndsWith(".json", StringComparison.OrdinalIgnoreCase);

    /// <summary>
    /// Creates (or replaces) the capture file <paramref name="path"/>: JSON lines when it ends in <c>.jsonl</c>,
    /// <c>.ndjson</c> or <c>.json</c>, else a pcap.
    /// </summary>
    /// <exception cref="IOException">The file cannot be created.</exception>
    /// <exception cref="UnauthorizedAccessException">The file may not be written.</exception>
    public static CaptureWriter Create(string path)
    {
        Guard.NotNull(path);
        var file = new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.Read, 64 * 1024);
        try
        {
            return IsJsonLines(path) ? new JsonLinesCaptureWriter(file) : new PcapCaptureWriter(file);
        }
        catch
        {
            file.Dispose();
            throw;
        }
    }

    /// <summary>Writes one record.</summary>
    /// <param name="time">When its last byte crossed the line.</param>
    /// <param name="direction">Which way.</param>
    /// <param name="bytes">The bytes, CR included.</param>
    /// <param name="flags">What else is known about them.</param>
    /// <param name="duration">From the first byte to the last, or zero.</param>
    public void Write(DateTimeOffset time, LineDirection direction, ReadOnlySpan<byte> bytes, CaptureFlags flags = CaptureFlags.None, TimeSpan duration = default)
    {
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            WriteRecord(_file, time, direction, bytes, flags, duration);
            Records++;
            if (!_dirty)
            {
                _dirty = true;
                _flush.Change(FlushDelay, Timeout.InfiniteTimeSpan);
            }
        }
    }

    /// <summary>Writes what is buffered to the file now.</summary>
    public void Flush()
    {
        lock (_gate)
        {
            if (!_disposed)
            {
                _file.Flush();
                _dirty = false;
            }
        }
    }

    /// <summary>Flushes and closes the file.</summary>
    public void Dispose()
    {
        lock (_gate)
        {
            if (_disposed)
            {
                return;
            }

            _disposed = true;
            _flush.Dispose();
            _file.Dispose();
        }
    }

    /// <summary>Writes one record in the format's layout (under the writer's lock).</summary>
    protected abstract void WriteRecord(Stream file, DateTimeOffset time, LineDirection direction, ReadOnlySpan<byte> bytes, CaptureFlags flags, TimeSpan duration);

    private void FlushIfDirty()
    {
        try
        {
            Flush();
        }
        catch (IOException)
        {
            // A full disk: the next record or the disposal reports it to whoever writes.
        }
    }
}
