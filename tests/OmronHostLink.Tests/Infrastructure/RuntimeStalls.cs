using System.Diagnostics;

namespace OmronHostLink.Tests.Infrastructure;

/// <summary>
/// Records when the runtime could not run a timer callback on time: a 5 ms timer on the thread pool, re-armed at each
/// callback, notes how much later than due each callback ran. A machine shared with other builds (load averages of
/// 30-40 on 2 cores) leaves the test process unscheduled for hundreds of milliseconds at times, and then no deadline
/// of any link can fire either. <see cref="StalledWithin"/> gives how much of an interval was lost that way, so a
/// real-clock bound can be checked on the time the process actually ran.
/// </summary>
internal sealed class RuntimeStalls : IAsyncDisposable
{
    private static readonly TimeSpan Period = TimeSpan.FromMilliseconds(5);

    /// <summary>Lateness below this is the timer's own granularity, not a stall.</summary>
    private static readonly long Granularity = Stopwatch.Frequency * 2 / 1000;

    private readonly object _gate = new();
    private readonly List<(long At, long Late)> _stalls = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;
    private long _maxLate;

    public RuntimeStalls() => _loop = RunAsync();

    /// <summary>The longest single stall seen.</summary>
    public TimeSpan Longest => TimeSpan.FromTicks(Interlocked.Read(ref _maxLate) * TimeSpan.TicksPerSecond / Stopwatch.Frequency);

    /// <summary>How much of the interval from <paramref name="start"/> to <paramref name="end"/> (Stopwatch timestamps) the runtime was stalled.</summary>
    public TimeSpan StalledWithin(long start, long end)
    {
        long stalled = 0;
        lock (_gate)
        {
            // Stalls end in time order; one that ended after the interval may still have begun inside it.
            for (int i = _stalls.Count - 1; i >= 0; i--)
            {
                (long at, long late) = _stalls[i];
                if (at - late > end)
                {
                    continue;
                }

                if (at < start && at < start - (Stopwatch.Frequency * 5))
                {
                    break;
                }

                long from = Math.Max(start, at - late);
                long to = Math.Min(end, at);
                if (to > from)
                {
                    stalled += to - from;
                }
            }
        }

        return TimeSpan.FromTicks(stalled * TimeSpan.TicksPerSecond / Stopwatch.Frequency);
    }

    public async ValueTask DisposeAsync()
    {
        _stop.Cancel();
        await _loop.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        _stop.Dispose();
    }

    private async Task RunAsync()
    {
        long periodTicks = Stopwatch.Frequency * Period.Ticks / TimeSpan.TicksPerSecond;
        using var tick = new PeriodicTimer(Period);
        long due = Stopwatch.GetTimestamp() + periodTicks;
        while (await tick.WaitForNextTickAsync(_stop.Token).ConfigureAwait(false))
        {
            long now = Stopwatch.GetTimestamp();
            long late = now - due;
            due = now + periodTicks;
            if (late > Granularity)
            {
                lock (_gate)
                {
                    _stalls.Add((now, late));
                }

                if (late > Interlocked.Read(ref _maxLate))
                {
                    Interlocked.Exchange(ref _maxLate, late);
                }
            }
        }
    }
}
