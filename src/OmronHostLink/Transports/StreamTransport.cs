namespace OmronHostLink.Transports;

/// <summary>A transport over a stream the caller already opened (an in-memory pipe in tests, a custom port). It cannot reopen a lost stream.</summary>
public sealed class StreamTransport : IHostLinkTransport, IDisposable
{
    private readonly bool _leaveOpen;
    private Stream? _stream;

    /// <summary>Creates the transport.</summary>
    /// <param name="stream">A readable and writable stream.</param>
    /// <param name="leaveOpen">True to leave the stream open when the transport is disposed.</param>
    /// <param name="lineTiming">The line's character timing, when known.</param>
    public StreamTransport(Stream stream, bool leaveOpen = false, LineTiming? lineTiming = null)
    {
        _stream = Guard.NotNull(stream);
        if (!stream.CanRead || !stream.CanWrite)
        {
            throw new ArgumentException("The stream must be readable and writable.", nameof(stream));
        }

        _leaveOpen = leaveOpen;
        LineTiming = lineTiming;
    }

    /// <inheritdoc/>
    public string Description => "stream";

    /// <inheritdoc/>
    public LineTiming? LineTiming { get; }

    /// <inheritdoc/>
    public ValueTask<Stream> OpenAsync(CancellationToken cancellationToken)
        => _stream is { } s
            ? new ValueTask<Stream>(s)
            : throw new HostLinkConnectionException("The stream was lost and a stream transport cannot reopen it.");

    /// <inheritdoc/>
    public async ValueTask CloseAsync()
    {
        Stream? s = Interlocked.Exchange(ref _stream, null);
        if (s is not null && !_leaveOpen)
        {
            await StreamCompat.DisposeAsync(s).ConfigureAwait(false);
        }
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => CloseAsync();

    /// <summary>Closes the stream synchronously (unless it is to be left open); the transport cannot reopen it.</summary>
    public void Dispose()
    {
        Stream? s = Interlocked.Exchange(ref _stream, null);
        if (s is not null && !_leaveOpen)
        {
            s.Dispose();
        }
    }
}
