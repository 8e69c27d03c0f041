namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Cuts one port's bytes into frames at each CR, in any fragmentation, keeping when each frame's first and last bytes
/// came. Bytes before an <c>@</c> in the same run are split off as not framing (noise, a frame whose start was lost);
/// a run of <see cref="Protocol.FrameReader.MaxFrameLength"/> bytes without a CR is given up as not framing, as a PLC's
/// port gives it up.
/// </summary>
internal sealed class FrameAssembler
{
    private readonly int _source;
    private readonly List<byte> _pending = new();
    private long _firstTicks;
    private long _firstEarliest;
    private long _atTicks;
    private long _atEarliest;

    public FrameAssembler(int source)
    {
        _source = source;
    }

    /// <summary>Takes one chunk, whose bytes arrived at or after <paramref name="earliest"/>, and returns the frames it completes.</summary>
    public void Take(TapChunk chunk, long earliest, List<MonitoredFrame> frames)
    {
        foreach (byte b in chunk.Bytes)
        {
            if (_pending.Count == 0)
            {
                _firstTicks = chunk.Ticks;
                _firstEarliest = earliest;
            }

            _pending.Add(b);
            if (b == (byte)'@')
            {
                _atTicks = chunk.Ticks;
                _atEarliest = earliest;
            }

            if (b == (byte)'\r')
            {
                Complete(chunk.Ticks, frames);
            }
            else if (_pending.Count > Protocol.FrameReader.MaxFrameLength)
            {
                frames.Add(new MonitoredFrame(_source, _pending.ToArray(), _firstTicks, chunk.Ticks, framed: false, _firstEarliest));
                _pending.Clear();
            }
        }
    }

    /// <summary>Returns what is left without a CR, as bytes that do not frame (at the end of monitoring).</summary>
    public void Flush(long ticks, List<MonitoredFrame> frames)
    {
        if (_pending.Count > 0)
        {
            frames.Add(new MonitoredFrame(_source, _pending.ToArray(), _firstTicks, ticks, framed: false, _firstEarliest));
            _pending.Clear();
        }
    }

    private void Complete(long lastTicks, List<MonitoredFrame> frames)
    {
        byte[] run = _pending.ToArray();
        _pending.Clear();
        int at = Array.LastIndexOf(run, (byte)'@');
        if (at > 0)
        {
            // '@' never appears inside a frame: what comes before the last one is not part of this frame.
            frames.Add(new MonitoredFrame(_source, run.AsSpan(0, at).ToArray(), _firstTicks, _atTicks, framed: false, _firstEarliest));
            frames.Add(new MonitoredFrame(_source, run.AsSpan(at).ToArray(), _atTicks, lastTicks, framed: true, _atEarliest));
            return;
        }

        frames.Add(new MonitoredFrame(_source, run, _firstTicks, lastTicks, framed: true, _firstEarliest));
    }
}
