using System.Diagnostics;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// The host's side of an emulated serial line: a write of N characters reaches the far end when its last stop bit
/// would, N × bits / baud after it starts (the simulator paces the other direction itself). Counts the characters
/// and the transmissions in both directions, so the theoretical minimum comes from what really crossed the line.
/// </summary>
internal sealed class PacedLineStream(Stream inner, int baudRate, int bitsPerCharacter) : PassThroughStream(inner)
{
    private static readonly TimeSpan SleepMargin = TimeSpan.FromMilliseconds(2);
    private readonly double _secondsPerCharacter = (double)bitsPerCharacter / baudRate;
    private long _sent;
    private long _received;
    private int _writes;

    public long Sent => Interlocked.Read(ref _sent);

    public long Received => Interlocked.Read(ref _received);

    /// <summary>Host transmissions (command frames and CR delimiters): each is one frame exchange.</summary>
    public int Writes => Volatile.Read(ref _writes);

    public void ResetCounters()
    {
        Interlocked.Exchange(ref _sent, 0);
        Interlocked.Exchange(ref _received, 0);
        Volatile.Write(ref _writes, 0);
    }

    public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
    {
        var clock = Stopwatch.StartNew();
        TimeSpan target = TimeSpan.FromSeconds(buffer.Length * _secondsPerCharacter);
        while (true)
        {
            TimeSpan left = target - clock.Elapsed - SleepMargin;
            if (left <= TimeSpan.Zero)
            {
                break;
            }

            await Task.Delay(left, cancellationToken).ConfigureAwait(false);
        }

        // The last stretch is spun without yielding: a yield on a loaded machine can cost a scheduler slice.
        while (clock.Elapsed < target)
        {
            Thread.SpinWait(20);
        }

        await Inner.WriteAsync(buffer, cancellationToken).ConfigureAwait(false);
        Interlocked.Add(ref _sent, buffer.Length);
        Interlocked.Increment(ref _writes);
    }

    public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        int n = await Inner.ReadAsync(buffer, cancellationToken).ConfigureAwait(false);
        Interlocked.Add(ref _received, n);
        return n;
    }
}
