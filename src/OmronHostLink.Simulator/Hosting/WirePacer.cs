using System.Diagnostics;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Writes bytes at the character rate of a serial line. A frame of N characters occupies the line for
/// N × bits-per-character / baud: its first byte is handed to the stream when the frame starts and its last when the
/// last stop bit ends, the bytes between spread evenly, so a receiver measures first-to-last = N × bits / baud.
/// </summary>
/// <remarks>
/// A paced write runs on its own thread, Stopwatch-timed: bytes before the last go out in batches about a
/// millisecond apart (sleeping between them), and the last byte is timed precisely (sleep, then a short spin). Doing the short waits on the thread
/// pool — spinning or re-queuing — starves the pool on small machines, and the receiver of these very bytes then
/// gets them in one late lump.
/// </remarks>
internal sealed class WirePacer
{
    private static readonly TimeSpan PreciseMargin = TimeSpan.FromMilliseconds(1.5);
    private static readonly TimeSpan MinSleep = TimeSpan.FromMilliseconds(1);

    private readonly double _secondsPerCharacter;

    public WirePacer(int baudRate, int bitsPerCharacter)
    {
        _secondsPerCharacter = baudRate > 0 ? (double)bitsPerCharacter / baudRate : 0;
    }

    public bool Enabled => _secondsPerCharacter > 0;

    /// <summary>The time <paramref name="characters"/> characters occupy the line.</summary>
    public TimeSpan WireTime(int characters) => TimeSpan.FromSeconds(characters * _secondsPerCharacter);

    /// <summary>
    /// When byte <paramref name="index"/> of a <paramref name="count"/>-byte transmission is handed over, from its start:
    /// the first at once, the last when its last stop bit ends (<see cref="WireTime"/> of the count), the others evenly between.
    /// </summary>
    internal TimeSpan DueTime(int index, int count) => count <= 1 ? TimeSpan.Zero : TimeSpan.FromSeconds(index * Step(count));

    /// <summary>How many bytes of a <paramref name="count"/>-byte transmission are due <paramref name="elapsed"/> after its start.</summary>
    internal int DueCount(TimeSpan elapsed, int count)
        => count <= 1 ? count : Math.Min(count, (int)Math.Floor((elapsed.TotalSeconds / Step(count)) + 1e-3) + 1);

    private double Step(int count) => count * _secondsPerCharacter / (count - 1);

    /// <summary>Writes <paramref name="bytes"/> at the line's pace.</summary>
    /// <returns>When the first byte was handed to the stream.</returns>
    public async Task<DateTimeOffset> WriteAsync(Stream stream, ReadOnlyMemory<byte> bytes, CancellationToken cancellationToken)
    {
        if (!Enabled)
        {
            DateTimeOffset first = DateTimeOffset.UtcNow;
            await stream.WriteAsync(bytes, cancellationToken).ConfigureAwait(false);
            await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
            return first;
        }

        return await Task.Factory.StartNew(
            () => Write(stream, bytes.Span, cancellationToken),
            cancellationToken,
            TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach,
            TaskScheduler.Default).ConfigureAwait(false);
    }

    /// <summary>Waits until <paramref name="target"/> precisely: sleeps while far, then spins without yielding.</summary>
    /// <remarks>
    /// Yielding (sched_yield) on a loaded machine can lose a whole scheduler slice (several ms) and make the last
    /// byte of a frame late; a sleeping thread that wakes is scheduled promptly, and the last ~1.5 ms are spun.
    /// </remarks>
    private static void WaitUntil(Stopwatch clock, TimeSpan target, CancellationToken cancellationToken)
    {
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            TimeSpan left = target - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                return;
            }

            if (left > PreciseMargin)
            {
                cancellationToken.WaitHandle.WaitOne(left - PreciseMargin);
                continue;
            }

            Thread.SpinWait(20);
        }
    }

    /// <summary>Waits about until <paramref name="target"/>, at least a millisecond, never spinning: for bytes before the last, whose exact moment does not matter.</summary>
    private static void SleepUntil(Stopwatch clock, TimeSpan target, CancellationToken cancellationToken)
    {
        TimeSpan left = target - clock.Elapsed;
        cancellationToken.WaitHandle.WaitOne(left > MinSleep ? left : MinSleep);
        cancellationToken.ThrowIfCancellationRequested();
    }

    /// <summary>Waits <paramref name="delay"/> precisely (the PLC's turnaround) off the thread pool.</summary>
    public Task DelayAsync(TimeSpan delay, CancellationToken cancellationToken)
    {
        if (delay <= TimeSpan.Zero)
        {
            return Task.CompletedTask;
        }

        return Task.Factory.StartNew(
            () => WaitUntil(Stopwatch.StartNew(), delay, cancellationToken),
            cancellationToken,
            TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach,
            TaskScheduler.Default);
    }

    private DateTimeOffset Write(Stream stream, ReadOnlySpan<byte> bytes, CancellationToken cancellationToken)
    {
        int n = bytes.Length;
        var clock = Stopwatch.StartNew();
        DateTimeOffset first = DateTimeOffset.UtcNow;
        if (n <= 1)
        {
            stream.Write(bytes);
            stream.Flush();
            WaitUntil(clock, WireTime(n), cancellationToken);
            return first;
        }

        int sent = 0;
        while (sent < n)
        {
            int due = DueCount(clock.Elapsed, n);
            if (due > sent)
            {
                stream.Write(bytes.Slice(sent, due - sent));
                stream.Flush();
                sent = due;
                continue;
            }

            TimeSpan next = DueTime(sent, n);
            if (sent == n - 1)
            {
                WaitUntil(clock, next, cancellationToken);
            }
            else
            {
                // Bytes before the last go out in ~1 ms batches: the receiver's timing hangs on the last byte only.
                SleepUntil(clock, next, cancellationToken);
            }
        }

        return first;
    }
}
