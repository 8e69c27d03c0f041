using OmronHostLink.Capture;

namespace OmronHostLink.Simulator;

/// <summary>
/// The frames a simulated line received and sent, with their times: kept in memory for tests and tools, and written to
/// a capture file (pcap for Wireshark, or JSON lines) when one is given. Set it as
/// <see cref="VirtualPlcOptions.FrameLog"/>; every session of the PLCs on the line writes to it. Thread-safe.
/// </summary>
public sealed class SimulatorFrameLog : IDisposable
{
    private readonly object _gate = new();
    private readonly List<SimulatorFrame>? _frames;
    private readonly CaptureWriter? _capture;
    private long _count;

    /// <summary>Creates a log that keeps every frame in memory.</summary>
    public SimulatorFrameLog()
        : this(null, keepFrames: true)
    {
    }

    /// <summary>Creates a log that writes every frame to <paramref name="captureFile"/> and keeps them in memory if asked.</summary>
    /// <param name="captureFile">A pcap file (a name not ending in .jsonl, .ndjson or .json) or JSON lines; created or replaced now. Null for none.</param>
    /// <param name="keepFrames">Whether <see cref="Frames"/> keeps them (a long run to a file need not).</param>
    /// <exception cref="IOException">The capture file cannot be created.</exception>
    /// <exception cref="UnauthorizedAccessException">The capture file may not be written.</exception>
    public SimulatorFrameLog(string? captureFile, bool keepFrames = false)
    {
        _frames = keepFrames ? new List<SimulatorFrame>() : null;
        _capture = captureFile is null ? null : CaptureWriter.Create(captureFile);
    }

    /// <summary>How many frames were logged.</summary>
    public long Count => Interlocked.Read(ref _count);

    /// <summary>A copy of the frames kept so far, in the order they crossed the line (empty when the log keeps none).</summary>
    public IReadOnlyList<SimulatorFrame> Frames
    {
        get
        {
            lock (_gate)
            {
                return _frames is null ? [] : _frames.ToArray();
            }
        }
    }

    /// <summary>Writes what is buffered to the capture file now.</summary>
    public void Flush() => _capture?.Flush();

    /// <summary>Closes the capture file; frames logged later are kept in memory only.</summary>
    public void Dispose() => _capture?.Dispose();

    internal void Received(ReadOnlySpan<byte> frame, DateTimeOffset time)
        => Add(new SimulatorFrame(true, time, time, frame.ToArray(), framed: true));

    internal void Sent(ReadOnlySpan<byte> bytes, DateTimeOffset firstByte, DateTimeOffset lastByte, bool framed)
        => Add(new SimulatorFrame(false, firstByte, lastByte, bytes.ToArray(), framed));

    private void Add(SimulatorFrame frame)
    {
        lock (_gate)
        {
            _frames?.Add(frame);
            Interlocked.Increment(ref _count);
            _capture?.Write(
                frame.Time,
                frame.FromHost ? LineDirection.ToPlc : LineDirection.FromPlc,
                frame.Bytes.Span,
                frame.IsFrame ? CaptureFlags.None : CaptureFlags.NotFramed,
                frame.Time - frame.FirstByteTime);
        }
    }
}
