using OmronHostLink.Capture;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// The monitor without its ports: chunks in, frames cut, exchanges paired, every frame written to the capture with its
/// direction, events out. With two ports, each port's frames are in order but the two ports' readers run on threads of
/// their own, so a frame of one may be handed over (and stamped) after a later frame of the other: the frames are merged
/// as the protocol orders them, taking the host's next frame when the host speaks next and the PLC's when the PLC does;
/// a frame of the side that does not speak next waits up to <see cref="ReorderWindow"/> for the other side's.
/// </summary>
internal sealed class LineMonitor
{
    /// <summary>How long a frame heard on one of two ports waits for the other side's frame that the protocol puts first.</summary>
    public static readonly TimeSpan ReorderWindow = TimeSpan.FromMilliseconds(50);

    private readonly bool _twoPorts;
    private readonly FrameAssembler[] _assemblers;
    private readonly ExchangePairer _pairer;
    private readonly MonitorClock _clock;
    private readonly CaptureWriter? _capture;
    private readonly Action<MonitorEvent> _report;
    private readonly List<MonitoredFrame> _cut = new();
    private readonly Queue<MonitoredFrame>[] _waiting = [new(), new()];
    private readonly List<MonitorEvent> _events = new();
    private readonly long _window;

    public LineMonitor(bool twoPorts, MonitorClock clock, CaptureWriter? capture, Action<MonitorEvent> report)
    {
        _twoPorts = twoPorts;
        _assemblers = twoPorts ? [new FrameAssembler(0), new FrameAssembler(1)] : [new FrameAssembler(0)];
        _pairer = new ExchangePairer(directionsKnown: twoPorts);
        _clock = clock;
        _capture = capture;
        _report = report;
        _window = (long)(ReorderWindow.TotalSeconds * System.Diagnostics.Stopwatch.Frequency);
    }

    /// <summary>Takes one chunk read from a port.</summary>
    public void Take(TapChunk chunk)
    {
        _cut.Clear();
        _assemblers[chunk.Source].Take(chunk, _cut);
        if (_twoPorts)
        {
            foreach (MonitoredFrame frame in _cut)
            {
                _waiting[frame.Source].Enqueue(frame);
            }

            Merge(chunk.Ticks);
        }
        else
        {
            foreach (MonitoredFrame frame in _cut)
            {
                Pair(frame);
            }
        }
    }

    /// <summary>Time has passed with no bytes: frames that waited long enough go on.</summary>
    public void Tick(long now)
    {
        if (_twoPorts)
        {
            Merge(now);
        }
    }

    /// <summary>Monitoring ends: everything held and open is reported.</summary>
    public void Flush(long now)
    {
        _cut.Clear();
        foreach (FrameAssembler assembler in _assemblers)
        {
            assembler.Flush(now, _cut);
        }

        foreach (MonitoredFrame frame in _cut)
        {
            _waiting[frame.Source].Enqueue(frame);
        }

        Merge(long.MaxValue);
        _events.Clear();
        _pairer.Flush(_events);
        Report();
    }

    /// <summary>Pairs the waiting frames of the two ports in the order the protocol gives them.</summary>
    private void Merge(long now)
    {
        Queue<MonitoredFrame> host = _waiting[0];
        Queue<MonitoredFrame> plc = _waiting[1];
        while (host.Count > 0 || plc.Count > 0)
        {
            Queue<MonitoredFrame> next = _pairer.PlcSpeaksNext ? plc : host;
            Queue<MonitoredFrame> other = ReferenceEquals(next, plc) ? host : plc;
            if (next.Count > 0 && (other.Count == 0 || !Long(other.Peek(), next.Peek().FirstTicks)))
            {
                Pair(next.Dequeue());
            }
            else if (other.Count > 0 && (next.Count > 0 || Long(other.Peek(), now)))
            {
                // The side that should speak has been silent too long (no answer; an answer nobody asked for), or its
                // frame came a whole window after this one: this one goes first.
                Pair(other.Dequeue());
            }
            else
            {
                return;
            }
        }
    }

    /// <summary>Whether <paramref name="frame"/> ended a whole reorder window before <paramref name="time"/>.</summary>
    private bool Long(MonitoredFrame frame, long time) => time - frame.LastTicks > _window;

    private void Pair(MonitoredFrame frame)
    {
        _events.Clear();
        _pairer.Take(frame, _events);
        _capture?.Write(
            _clock.At(frame.LastTicks),
            frame.Direction,
            frame.Bytes,
            frame.IsFrame ? CaptureFlags.None : CaptureFlags.NotFramed,
            MonitorClock.Between(frame.FirstTicks, frame.LastTicks));
        Report();
    }

    private void Report()
    {
        foreach (MonitorEvent e in _events)
        {
            _report(e);
        }
    }
}
