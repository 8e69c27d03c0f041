using System.Collections.Concurrent;
using Microsoft.Extensions.Time.Testing;

namespace OmronHostLink.Testing;

/// <summary>
/// A <see cref="FakeTimeProvider"/> that reports each timer the code under test arms, with its due time: the positive
/// event a test waits for before asserting that something has not happened yet (the code is waiting on this clock,
/// so nothing can happen until the test advances it).
/// </summary>
public sealed class TimerRecordingTimeProvider : FakeTimeProvider
{
    private readonly ConcurrentQueue<TimeSpan> _armed = new();
    private long _unrunTicks;

    /// <summary>Every due time armed so far, in order (infinite ones left out).</summary>
    public IReadOnlyList<TimeSpan> Armed => _armed.ToArray();

    /// <inheritdoc/>
    public override ITimer CreateTimer(TimerCallback callback, object? state, TimeSpan dueTime, TimeSpan period)
    {
        ITimer timer = base.CreateTimer(callback, state, dueTime, period);
        if (dueTime != Timeout.InfiniteTimeSpan)
        {
            _armed.Enqueue(dueTime);
        }

        return timer;
    }

    /// <summary>
    /// Moves the timestamp clock forward by <paramref name="delta"/> without running the timers due meanwhile: a busy host,
    /// where the code reads the later time before a due timer's callback has run. Those timers run at the next
    /// <see cref="FakeTimeProvider.Advance"/> that reaches them on the fake clock, which this does not move.
    /// </summary>
    public void AdvanceWithoutTimers(TimeSpan delta) => Interlocked.Add(ref _unrunTicks, delta.Ticks);

    /// <inheritdoc/>
    public override long GetTimestamp()
        => base.GetTimestamp() + (Interlocked.Read(ref _unrunTicks) * TimestampFrequency / TimeSpan.TicksPerSecond);

    /// <summary>Waits until <paramref name="count"/> timers with a finite due time have been armed (created with one).</summary>
    public Task ArmedAsync(int count) => Eventually.UntilAsync(() => _armed.Count >= count, $"{count} timers are armed on the fake clock");
}
