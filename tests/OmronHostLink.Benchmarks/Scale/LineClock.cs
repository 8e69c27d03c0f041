using System.Diagnostics;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// Wakes waiters at <see cref="Stopwatch"/> timestamps to within a few tenths of a millisecond, from one thread of its
/// own that sleeps on a monitor until the earliest is due — no spinning, so it costs next to nothing at thousands of
/// wake-ups a second.
/// </summary>
/// <remarks>
/// <c>Task.Delay</c> is not precise enough for line pacing here: on Linux the runtime's timers run on a coarse clock
/// (the kernel tick, 4 ms on this machine), and a 17 ms delay measured 2–4 ms late, which would lengthen every
/// emulated transaction by that much. A monitor wait is timed by the kernel's high-resolution clock (about 0.1 ms late).
/// </remarks>
internal sealed class LineClock : IDisposable
{
    private static readonly long Tolerance = Stopwatch.Frequency * 3 / 10_000; // 0.3 ms: fire rather than sleep again
    private readonly PriorityQueue<TaskCompletionSource, long> _due = new();
    private readonly Thread _thread;
    private bool _disposed;

    public LineClock()
    {
        _thread = new Thread(Run) { IsBackground = true, Name = "line clock" };
        _thread.Start();
    }

    /// <summary>Completes at <paramref name="timestamp"/> (at once if it has passed); continuations run on the thread pool.</summary>
    public Task WaitUntilAsync(long timestamp, CancellationToken cancellationToken)
    {
        if (timestamp - Stopwatch.GetTimestamp() <= Tolerance)
        {
            return Task.CompletedTask;
        }

        var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        lock (_due)
        {
            ObjectDisposedException.ThrowIf(_disposed, this);
            bool earliest = !_due.TryPeek(out _, out long head) || timestamp < head;
            _due.Enqueue(done, timestamp);
            if (earliest)
            {
                Monitor.Pulse(_due);
            }
        }

        return done.Task.WaitAsync(cancellationToken);
    }

    public void Dispose()
    {
        lock (_due)
        {
            _disposed = true;
            while (_due.TryDequeue(out TaskCompletionSource? waiter, out _))
            {
                waiter.TrySetCanceled();
            }

            Monitor.Pulse(_due);
        }

        _thread.Join(TimeSpan.FromSeconds(5));
    }

    private void Run()
    {
        lock (_due)
        {
            while (!_disposed)
            {
                if (!_due.TryPeek(out _, out long head))
                {
                    Monitor.Wait(_due);
                    continue;
                }

                long left = head - Stopwatch.GetTimestamp();
                if (left <= Tolerance)
                {
                    _due.Dequeue().TrySetResult();
                    continue;
                }

                Monitor.Wait(_due, Math.Max(1, (int)(left * 1000 / Stopwatch.Frequency)));
            }
        }
    }
}
