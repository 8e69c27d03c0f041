namespace OmronHostLink.Transports;

/// <summary>
/// An open serial port as the link's stream: the port's <c>BaseStream</c>, with what the link needs on top. Disposing
/// it closes the port, which also ends a pending read (on Windows the read ignores its cancellation token, so closing
/// the port is what frees it). When the device goes away, reads and writes fail with an <see cref="IOException"/> that
/// says so, and every later call fails at once: System.IO.Ports on Unix reports a hang-up as "the port is closed" and
/// stops serving the port.
/// </summary>
internal sealed class SerialLineStream : Stream
{
    private readonly ISerialPort _port;
    private readonly Stream _inner;
    private volatile bool _disposed;
    private volatile IOException? _lost;

    public SerialLineStream(ISerialPort port)
    {
        _port = port;
        _inner = port.BaseStream;
    }

    public override bool CanRead => !_disposed;

    public override bool CanWrite => !_disposed;

    public override bool CanSeek => false;

    public override long Length => throw new NotSupportedException("A serial port has no length.");

    public override long Position
    {
        get => throw new NotSupportedException("A serial port has no position.");
        set => throw new NotSupportedException("A serial port has no position.");
    }

    /// <summary>Nothing to do: a write has handed its bytes to the driver when it completes, and draining the driver would only hold a thread until they are on the wire.</summary>
    public override void Flush() => ThrowIfUnusable();

    public override Task FlushAsync(CancellationToken cancellationToken)
    {
        if (cancellationToken.IsCancellationRequested)
        {
            return Task.FromCanceled(cancellationToken);
        }

        ThrowIfUnusable();
        return Task.CompletedTask;
    }

    public override int Read(byte[] buffer, int offset, int count)
    {
        ThrowIfUnusable();
        try
        {
            return _inner.Read(buffer, offset, count);
        }
        catch (Exception e) when (IsLoss(e))
        {
            throw Lost(e);
        }
    }

    public override void Write(byte[] buffer, int offset, int count)
    {
        ThrowIfUnusable();
        try
        {
            _inner.Write(buffer, offset, count);
        }
        catch (Exception e) when (IsLoss(e))
        {
            throw Lost(e);
        }
    }

    public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ThrowIfUnusable();
        return Translate(_inner.ReadAsync(buffer, offset, count, cancellationToken));
    }

    public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
    {
        ThrowIfUnusable();
        return Translate(_inner.WriteAsync(buffer, offset, count, cancellationToken));
    }

#if NET
    public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        ThrowIfUnusable();
        ValueTask<int> read = _inner.ReadAsync(buffer, cancellationToken);
        return read.IsCompletedSuccessfully ? read : new ValueTask<int>(Translate(read.AsTask()));
    }

    public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
    {
        ThrowIfUnusable();
        ValueTask write = _inner.WriteAsync(buffer, cancellationToken);
        return write.IsCompletedSuccessfully ? write : new ValueTask(Translate(write.AsTask()));
    }
#endif

    public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException("A serial port cannot seek.");

    public override void SetLength(long value) => throw new NotSupportedException("A serial port has no length.");

    protected override void Dispose(bool disposing)
    {
        if (disposing && !_disposed)
        {
            _disposed = true;
            try
            {
                _port.Dispose();
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException or ObjectDisposedException)
            {
                // Closing a port whose device is gone (a USB adapter unplugged) can fail on Windows: nothing is left to close.
            }
        }

        base.Dispose(disposing);
    }

    private async Task<int> Translate(Task<int> operation)
    {
        try
        {
            return await operation.ConfigureAwait(false);
        }
        catch (Exception e) when (IsLoss(e))
        {
            throw Lost(e);
        }
    }

    private async Task Translate(Task operation)
    {
        try
        {
            await operation.ConfigureAwait(false);
        }
        catch (Exception e) when (IsLoss(e))
        {
            throw Lost(e);
        }
    }

    /// <summary>A failure of the device, as opposed to our own disposal or a cancellation.</summary>
    private bool IsLoss(Exception e)
        => !_disposed && e is IOException or ObjectDisposedException or InvalidOperationException or TimeoutException or UnauthorizedAccessException;

    private IOException Lost(Exception e)
    {
        IOException lost = _lost ?? new IOException(
            e is TimeoutException
                ? "a write did not complete within the port's write timeout (flow control held it)"
                : $"the device hung up or failed{(e is IOException ? $" ({e.Message.TrimEnd('.')})" : "")}: a USB adapter unplugged, or the other end of a pseudo-terminal closed",
            e);
        _lost = lost;
        return lost;
    }

    private void ThrowIfUnusable()
    {
        if (_disposed)
        {
            throw new ObjectDisposedException(nameof(SerialLineStream), $"Serial port {_port.PortName} has been closed.");
        }

        if (_lost is { } lost)
        {
            throw new IOException(lost.Message, lost);
        }
    }
}
