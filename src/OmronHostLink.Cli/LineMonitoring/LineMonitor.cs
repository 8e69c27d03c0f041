using OmronHostLink.Capture;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// The monitor without its ports: chunks in, frames cut, exchanges paired, every frame written to the capture with its
/// direction, events out. With two ports, each port's frames are in order but the two ports' readers run on threads of
/// their own, and a reader that runs late hands its frames over (and stamps them) late: neither the order chunks come in
/// nor their stamps alone say which side spoke first. Each frame therefore carries when it may first have arrived (its
/// reader's watermark before the read, <see cref="TapChunk.Clear"/>) and when it had arrived at the latest (the read's
/// return). The frames are merged as the protocol orders them — the PLC's next frame when the PLC speaks next, the
/// host's when the host does — unless the other side's frame provably came first (it had ended before the next side's
/// frame can have begun: a command nobody answered, an answer nobody asked for). A frame of the side that does not speak
/// next is held until the other port's reader has provably read past it (its watermark is later than the frame): then
/// nothing that came before it can still be unread, however late either reader ran.
/// </summary>
/// <remarks>
/// A reader proves its port quiet with a poll that timed out and proves it read everything with a read that did not fill
/// its buffer (<see cref="SerialTap"/>). A reader that cannot (<c>readersProveQuiet</c> false: the port's own stream on
/// Windows) has its watermark moved by the clock instead: a port that handed over nothing for
/// <see cref="QuietWindow"/> is taken as quiet up to that long ago.
/// </remarks>
internal sealed class LineMonitor
{
    /// <summary>Where readers cannot prove a port quiet: how long a port must hand over nothing to be taken as quiet.</summary>
    public static readonly TimeSpan QuietWindow = TimeSpan.FromMilliseconds(50);

    private readonly bool _twoPorts;
    private readonly bool _readersProveQuiet;
    private readonly FrameAssembler[] _assemblers;
    private readonly ExchangePairer _pairer;
    private readonly MonitorClock _clock;
    private readonly CaptureWriter? _capture;
    private readonly Action<MonitorEvent> _report;
    private readonly List<MonitoredFrame> _cut = new();
    private readonly Queue<MonitoredFrame>[] _waiting = [new(), new()];
    private readonly long[] _clear = new long[2];
    private readonly List<MonitorEvent> _events = new();
    private readonly long _quietWindow;

    public LineMonitor(bool twoPorts, MonitorClock clock, CaptureWriter? capture, Action<MonitorEvent> report, bool readersProveQuiet = true)
    {
        _twoPorts = twoPorts;
        _readersProveQuiet = readersProveQuiet;
        _assemblers = twoPorts ? [new FrameAssembler(0), new FrameAssembler(1)] : [new FrameAssembler(0)];
        _pairer = new ExchangePairer(directionsKnown: twoPorts);
        _clock = clock;
        _capture = capture;
        _report = report;
        _quietWindow = (long)(QuietWindow.TotalSeconds * System.Diagnostics.Stopwatch.Frequency);
    }

    /// <summary>Takes one chunk read from a port (or its reader's watermark alone).</summary>
    public void Take(TapChunk chunk)
    {
        _cut.Clear();
        long earliest = _clear[chunk.Source];
        _clear[chunk.Source] = Math.Max(earliest, chunk.Clear);
        _assemblers[chunk.Source].Take(chunk, earliest, _cut);
        if (_twoPorts)
        {
            foreach (MonitoredFrame frame in _cut)
            {
                _waiting[frame.Source].Enqueue(frame);
            }

            Merge(flush: false);
        }
        else
        {
            foreach (MonitoredFrame frame in _cut)
            {
                Pair(frame);
            }
        }
    }

    /// <summary>Time has passed: where readers cannot prove a port quiet, the clock moves their watermarks.</summary>
    public void Tick(long now)
    {
        if (_twoPorts && !_readersProveQuiet)
        {
            _clear[0] = Math.Max(_clear[0], now - _quietWindow);
            _clear[1] = Math.Max(_clear[1], now - _quietWindow);
            Merge(flush: false);
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

        Merge(flush: true);
        _events.Clear();
        _pairer.Flush(_events);
        Report();
    }

    /// <summary>Frames held for a port's reader to catch up (two ports), for tests.</summary>
    internal int Held => _waiting[0].Count + _waiting[1].Count;

    /// <summary>Pairs the waiting frames of the two ports in line order (see the class's summary).</summary>
    private void Merge(bool flush)
    {
        while (_waiting[0].Count > 0 || _waiting[1].Count > 0)
        {
            int nextSide = _pairer.PlcSpeaksNext ? 1 : 0;
            int otherSide = 1 - nextSide;
            Queue<MonitoredFrame> next = _waiting[nextSide];
            Queue<MonitoredFrame> other = _waiting[otherSide];
            if (next.Count > 0)
            {
                MonitoredFrame expected = next.Peek();
                if (other.Count > 0 && other.Peek().LastTicks < expected.EarliestTicks)
                {
                    // The other side's frame had ended before the expected one can have begun.
                    Pair(other.Dequeue());
                }
                else if (other.Count > 0 || flush || _clear[otherSide] >= expected.EarliestTicks)
                {
                    // Nothing of the other side's, heard or still unread, provably came first.
                    Pair(next.Dequeue());
                }
                else
                {
                    return;
                }
            }
            else if (flush || _clear[nextSide] >= other.Peek().LastTicks)
            {
                // The side that speaks next had read past this frame and said nothing before it: no answer, an answer
                // nobody asked for.
                Pair(other.Dequeue());
            }
            else
            {
                return;
            }
        }
    }

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
