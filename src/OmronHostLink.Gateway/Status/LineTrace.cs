namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The trace of one link: its last frames, numbered, in a ring of fixed size, each answer with the time since the frame
/// before it went out. Frames arrive only while the link's tap is attached (<see cref="LineTraces"/>), that is while a
/// page watches.
/// </summary>
/// <param name="capacity">How many frames are kept (<c>Status:TraceFrames</c>).</param>
internal sealed class LineTrace(int capacity)
{
    private readonly TracedFrame?[] _ring = new TracedFrame?[capacity];
    private long _last;
    private DateTimeOffset? _lastOut;

    /// <summary>The number of the last frame taken; 0 before any.</summary>
    public long Last
    {
        get
        {
            lock (_ring)
            {
                return _last;
            }
        }
    }

    /// <summary>Takes a frame from the link's tap.</summary>
    public void Add(LinkFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        lock (_ring)
        {
            TimeSpan? latency = !frame.ToPlc && _lastOut is { } sent ? frame.Time - sent : null;
            if (frame.ToPlc)
            {
                _lastOut = frame.Time;
            }

            _last++;
            _ring[_last % _ring.Length] = new TracedFrame(_last, frame, latency);
        }
    }

    /// <summary>
    /// The frames kept after number <paramref name="after"/>, oldest first, and how many of those after it are no longer
    /// kept (overwritten before they were asked for).
    /// </summary>
    public (List<TracedFrame> Frames, long Lost) After(long after)
    {
        lock (_ring)
        {
            long first = Math.Max(after + 1, _last - _ring.Length + 1);
            var frames = new List<TracedFrame>((int)Math.Max(0, _last - first + 1));
            for (long seq = Math.Max(first, 1); seq <= _last; seq++)
            {
                frames.Add(_ring[seq % _ring.Length]!);
            }

            return (frames, Math.Max(0, first - after - 1));
        }
    }

    /// <summary>Forgets the time of the last frame out: the next answer after the tap is attached again has no latency.</summary>
    public void Paused()
    {
        lock (_ring)
        {
            _lastOut = null;
        }
    }
}
