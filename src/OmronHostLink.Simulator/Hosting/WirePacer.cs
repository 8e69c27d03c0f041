using System.Diagnostics;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Writes bytes at the character rate of a serial line. A frame of N characters occupies the line for
/// N × bits-per-character / baud: its first byte is handed to the stream when the frame starts and its last when the
/// last stop bit ends, the bytes between spread evenly, so a receiver measures first-to-last = N × bits / baud.
/// Waits above ~15 ms use <see cref="Task.Delay(TimeSpan, CancellationToken)"/>; shorter ones spin (timer resolution
/// is too coarse for 1 ms character times).
/// </summary>
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
        int n = bytes.Length;
        if (!Enabled || n <= 1)
        {
            await stream.WriteAsync(bytes, cancellationToken).ConfigureAwait(false);
            await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
            if (Enabled)
            {
                await WaitUntilAsync(Stopwatch.StartNew(), WireTime(n), cancellationToken).ConfigureAwait(false);
            }

            return;
        }

        double total = n * _secondsPerCharacter;
        double step = total / (n - 1);
        var clock = Stopwatch.StartNew();
        int sent = 0;
        while (sent < n)
        {
            double elapsed = clock.Elapsed.TotalSeconds;
            int due = Math.Min(n, (int)Math.Floor(elapsed / step) + 1);
            if (due > sent)
            {
                await stream.WriteAsync(bytes.Slice(sent, due - sent), cancellationToken).ConfigureAwait(false);
                await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
                sent = due;
                continue;
            }

            await WaitUntilAsync(clock, TimeSpan.FromSeconds(sent * step), cancellationToken).ConfigureAwait(false);
        }
    }

    private static async Task WaitUntilAsync(Stopwatch clock, TimeSpan target, CancellationToken cancellationToken)
    {
        while (true)
        {
            TimeSpan left = target - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                return;
            }

            if (left > SleepThreshold)
            {
                await Task.Delay(left - SleepThreshold, cancellationToken).ConfigureAwait(false);
                continue;
            }

            cancellationToken.ThrowIfCancellationRequested();
            Thread.Yield();
        }
    }
}
