using System.Diagnostics;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// The host's side of an emulated serial line: a write of N characters reaches the far end when its last stop bit
/// would, N × bits / baud after it starts (the simulator paces the other direction itself). Counts the characters
/// and the transmissions in both directions, so the theoretical minimum comes from what really crossed the line.
/// </summary>
internal sealed class PacedLineStream(Stream inner, int baudRate, int bitsPerCharacter) : Stream
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

    public override bool CanRead => true;

    public override bool CanSeek => false;

    public override bool CanWrite => true;

    public override long Length => throw new NotSupportedException();

    public override long Position
    {
        get => throw new NotSupportedException();
        set => throw new NotSupportedException();
    }

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

        await inner.WriteAsync(buffer, cancellationToken).ConfigureAwait(false);
        Interlocked.Add(ref _sent, buffer.Length);
        Interlocked.Increment(ref _writes);
    }

    public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        => WriteAsync(buffer.AsMemory(offset, count), cancellationToken).AsTask();

    public override void Write(byte[] buffer, int offset, int count) => WriteAsync(buffer, offset, count, CancellationToken.None).GetAwaiter().GetResult();

    public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        int n = await inner.ReadAsync(buffer, cancellationToken).ConfigureAwait(false);
        Interlocked.Add(ref _received, n);
        return n;
    }

    public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        => ReadAsync(buffer.AsMemory(offset, count), cancellationToken).AsTask();

    public override int Read(byte[] buffer, int offset, int count) => ReadAsync(buffer, offset, count, CancellationToken.None).GetAwaiter().GetResult();

    public override void Flush() => inner.Flush();

    public override Task FlushAsync(CancellationToken cancellationToken) => inner.FlushAsync(cancellationToken);

    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

    public override void SetLength(long value) => throw new NotSupportedException();

    protected override void Dispose(bool disposing)
    {
        if (disposing)
        {
            inner.Dispose();
        }

        base.Dispose(disposing);
    }
}
