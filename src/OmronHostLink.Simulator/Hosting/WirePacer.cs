using System.Diagnostics;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Writes bytes at the character rate of a serial line. A frame of N characters occupies the line for
/// N × bits-per-character / baud: its first byte is handed to the stream when the frame starts and its last when the
/// last stop bit ends, the bytes between spread evenly, so a receiver measures first-to-last = N × bits / baud.
/// </summary>
/// <remarks>
/// A paced write runs on its own thread, Stopwatch-timed: it sleeps through waits above ~15 ms (timer resolution) and
/// yields the processor for shorter ones (a character at 9600 bps lasts 1.15 ms). Doing the short waits on the thread
/// pool — spinning or re-queuing — starves the pool on small machines, and the receiver of these very bytes then
/// gets them in one late lump.
/// </remarks>
internal sealed class WirePacer
{
    private static readonly TimeSpan SleepThreshold = TimeSpan.FromMilliseconds(15);

    private readonly double _secondsPerCharacter;

    public WirePacer(int baudRate, int bitsPerCharacter)
    {
        _secondsPerCharacter = baudRate > 0 ? (double)bitsPerCharacter / baudRate : 0;
    }

    public bool Enabled => _secondsPerCharacter > 0;

    /// <summary>The time <paramref name="characters"/> characters occupy the line.</summary>
    public TimeSpan WireTime(int characters) => TimeSpan.FromSeconds(characters * _secondsPerCharacter);

    public async Task WriteAsync(Stream stream, ReadOnlyMemory<byte> bytes, CancellationToken cancellationToken)
    {
        if (!Enabled)
        {
            await stream.WriteAsync(bytes, cancellationToken).ConfigureAwait(false);
            await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
            return;
        }

        await Task.Factory.StartNew(
            () => Write(stream, bytes.Span, cancellationToken),
            cancellationToken,
            TaskCreationOptions.LongRunning | TaskCreationOptions.DenyChildAttach,
            TaskScheduler.Default).ConfigureAwait(false);
    }

    private static void WaitUntil(Stopwatch clock, TimeSpan target, CancellationToken cancellationToken)
    {
        var spinner = default(SpinWait);
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            TimeSpan left = target - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                return;
            }

            if (left > SleepThreshold)
            {
                cancellationToken.WaitHandle.WaitOne(left - SleepThreshold);
                continue;
            }

            // Yield the processor without ever falling into a 1 ms sleep late in the wait.
            spinner.SpinOnce(sleep1Threshold: -1);
        }
    }

    private void Write(Stream stream, ReadOnlySpan<byte> bytes, CancellationToken cancellationToken)
    {
        int n = bytes.Length;
        var clock = Stopwatch.StartNew();
        if (n <= 1)
        {
            stream.Write(bytes);
            stream.Flush();
            WaitUntil(clock, WireTime(n), cancellationToken);
            return;
        }

        double step = n * _secondsPerCharacter / (n - 1);
        int sent = 0;
        while (sent < n)
        {
            int due = Math.Min(n, (int)Math.Floor(clock.Elapsed.TotalSeconds / step) + 1);
            if (due > sent)
            {
                stream.Write(bytes.Slice(sent, due - sent));
                stream.Flush();
                sent = due;
                continue;
            }

            WaitUntil(clock, TimeSpan.FromSeconds(sent * step), cancellationToken);
        }
    }
}
