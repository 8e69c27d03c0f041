using OmronHostLink.Capture;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// The monitor without its ports: chunks in, frames cut, exchanges paired, every frame written to the capture with its
/// direction, events out. With two ports the frames of both are put back in the order they crossed the line (each
/// port's reader runs on its own thread, so a frame of one may be handed over after a later frame of the other): a frame
/// is held until <see cref="ReorderWindow"/> has passed since it ended.
/// </summary>
internal sealed class LineMonitor
{
    /// <summary>How long a frame heard on one of two ports waits for earlier frames of the other.</summary>
    public static readonly TimeSpan ReorderWindow = TimeSpan.FromMilliseconds(20);

    private readonly bool _twoPorts;
    private readonly FrameAssembler[] _assemblers;
    private readonly ExchangePairer _pairer;
    private readonly MonitorClock _clock;
    private readonly CaptureWriter? _capture;
    private readonly Action<MonitorEvent> _report;
    private readonly List<MonitoredFrame> _cut = new();
    private readonly List<MonitoredFrame> _held = new();
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
            _held.AddRange(_cut);
            Release(chunk.Ticks - _window);
        }
        else
        {
            foreach (MonitoredFrame frame in _cut)
            {
                Pair(frame);
            }
        }
    }

    /// <summary>Time has passed with no bytes: frames held for reordering that are old enough go on.</summary>
    public void Tick(long now)
    {
        if (_twoPorts)
        {
            Release(now - _window);
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

        _held.AddRange(_cut);
        Release(long.MaxValue);
        _events.Clear();
        _pairer.Flush(_events);
        Report();
    }

    private void Release(long before)
    {
        if (_held.Count == 0)
        {
            return;
        }

        _held.Sort(static (a, b) => a.LastTicks.CompareTo(b.LastTicks));
        int released = 0;
        while (released < _held.Count && _held[released].LastTicks <= before)
        {
            Pair(_held[released]);
            released++;
        }

        _held.RemoveRange(0, released);
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
