using Microsoft.Extensions.Time.Testing;

namespace OmronHostLink.Tests.Infrastructure;

/// <summary>
/// A fake clock that tells when a timer is created, so a test advances time only once the code under test waits on
/// it: each step is then exactly one scheduled wait, with no race between the test and the waiting code.
/// </summary>
internal sealed class SteppingClock : FakeTimeProvider
{
    private readonly SemaphoreSlim _timers = new(0);
    private int _created;

    public SteppingClock()
        : base(new DateTimeOffset(2026, 1, 1, 8, 0, 0, TimeSpan.Zero))
    {
    }

    /// <summary>Timers created so far.</summary>
    public int TimersCreated => Volatile.Read(ref _created);

    /// <summary>The wait asked for by the timer created last.</summary>
    public TimeSpan LastDueTime { get; private set; }

    /// <summary>
    /// How far the timestamps (<see cref="TimeProvider.GetTimestamp"/>) run behind the timers' clock: a timer then
    /// fires before its time by the timestamps, as the system timer can by the stopwatch's clock.
    /// </summary>
    public TimeSpan TimestampLag { get; set; }

    public override long GetTimestamp()
        => base.GetTimestamp() - (long)(TimestampLag.Ticks * (double)TimestampFrequency / TimeSpan.TicksPerSecond);

    public override ITimer CreateTimer(TimerCallback callback, object? state, TimeSpan dueTime, TimeSpan period)
    {
        ITimer timer = base.CreateTimer(callback, state, dueTime, period);
        LastDueTime = dueTime;
        Interlocked.Increment(ref _created);
        _timers.Release();
        return timer;
    }

    /// <summary>Waits until the code under test waits on a new timer (at most 10 s, then fails).</summary>
    public async Task NextTimerAsync()
    {
        if (!await _timers.WaitAsync(TimeSpan.FromSeconds(10)))
        {
            throw new TimeoutException("The code under test did not start waiting on the clock within 10 s.");
        }
    }

    /// <summary>Waits for the next timer, then moves the clock on by <paramref name="step"/>.</summary>
    public async Task StepAsync(TimeSpan step)
    {
        await NextTimerAsync();
        Advance(step);
    }
}
