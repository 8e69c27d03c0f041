using Microsoft.Extensions.Logging;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The transport as the link holds it: opened on demand into a <see cref="FrameChannel"/>, closed when the stream is
/// lost or the link closes, closed at once (from any thread, waiting for nothing) when the client is disposed. The
/// connection calls it under its gate, except <see cref="CloseAtOnce"/>.
/// </summary>
internal sealed class LinkTransport
{
    private readonly IHostLinkTransport _transport;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly HostLinkInstruments _instruments;
    private readonly string _linkName;

    private volatile FrameChannel? _channel;
    private volatile bool _disposed;
    private int _closedAtOnce;

    public LinkTransport(IHostLinkTransport transport, ILogger logger, TimeProvider time, HostLinkInstruments instruments, string linkName)
    {
        _transport = transport;
        _logger = logger;
        _time = time;
        _instruments = instruments;
        _linkName = linkName;
    }

    /// <summary>The transport itself (what telemetry names).</summary>
    public IHostLinkTransport Transport => _transport;

    public string Description => _transport.Description;

    /// <summary>How often the transport has been opened.</summary>
    public long Openings { get; private set; }

    /// <summary>Whether the link was disposed (or is being disposed): nothing opens it again.</summary>
    public bool IsDisposed => _disposed;

    /// <summary>Whether <see cref="CloseAtOnce"/> ran.</summary>
    public bool ClosedAtOnce => Volatile.Read(ref _closedAtOnce) == 1;

    /// <summary>The channel over the open stream, or null when the transport is closed.</summary>
    /// <exception cref="ObjectDisposedException">The link was disposed.</exception>
    public FrameChannel? OpenChannel()
        => _disposed ? throw new ObjectDisposedException(nameof(HostLinkConnection), $"The link to {_transport.Description} is closed.") : _channel;

    /// <summary>Stops the channel and closes the transport; a lost stream's own failure to close is ignored.</summary>
    public async ValueTask CloseAsync(bool lost)
    {
        FrameChannel? channel = _channel;
        _channel = null;
        channel?.RequestStop();
        try
        {
            await _transport.CloseAsync().ConfigureAwait(false);
        }
        catch (Exception e) when (lost && e is IOException or ObjectDisposedException)
        {
        }

        if (channel is not null)
        {
            await channel.WaitStoppedAsync().ConfigureAwait(false);
            _instruments.Connection(_linkName, -1);
        }
    }

    /// <summary>Closes the link for good and disposes the transport (the connection waited for its gate).</summary>
    public async ValueTask DisposeAsync()
    {
        _disposed = true;
        await CloseAsync(lost: false).ConfigureAwait(false);
        await _transport.DisposeAsync().ConfigureAwait(false);
    }

    /// <summary>Marks the link disposed without closing anything (it was closed at once before).</summary>
    public void MarkDisposed() => _disposed = true;

    /// <summary>
    /// Closes the link at once, from any thread: an exchange in progress fails with a
    /// <see cref="HostLinkConnectionException"/> and the transport is closed synchronously where it can be.
    /// </summary>
    /// <returns>False when it had run before.</returns>
    public bool CloseAtOnce()
    {
        _disposed = true;
        if (Interlocked.Exchange(ref _closedAtOnce, 1) == 1)
        {
            return false;
        }

        _channel?.Abort(DisposedDuringExchange());
        CloseTransportSynchronously();
        return true;
    }

    /// <summary>After <see cref="CloseAtOnce"/> between exchanges: lets go of the aborted channel.</summary>
    public void ForgetChannel()
    {
        if (_channel is not null)
        {
            _channel = null;
            _instruments.Connection(_linkName, -1);
        }
    }

    /// <summary>Opens the transport and starts a channel over its stream.</summary>
    /// <exception cref="ObjectDisposedException">The link was disposed.</exception>
    public async ValueTask<FrameChannel> OpenAsync(CancellationToken cancellationToken)
    {
        _ = OpenChannel();
        Stream stream = await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        var channel = new FrameChannel(stream, _transport.Description, _logger, _time);
        _channel = channel;
        if (_disposed)
        {
            // Closed at once while the transport was opening: that may have missed this stream and this channel.
            channel.Abort(DisposedDuringExchange());
            CloseTransportSynchronously();
            _channel = null;
            throw DisposedDuringExchange();
        }

        Openings++;
        channel.Start();
        _instruments.Connection(_linkName, +1);
        HostLinkLog.Opened(_logger, _transport.Description);
        return channel;
    }

    private HostLinkConnectionException DisposedDuringExchange()
        => new($"The client was disposed: the link to {_transport.Description} was closed during the exchange.", new ObjectDisposedException(nameof(HostLinkConnection)));

    /// <summary>Closes the transport without waiting: synchronously where it can (every built-in transport does).</summary>
    private void CloseTransportSynchronously()
    {
        try
        {
            if (_transport is IDisposable disposable)
            {
                disposable.Dispose();
            }
            else
            {
                _ = ObserveAsync(_transport.DisposeAsync());
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException or UnauthorizedAccessException or System.Net.Sockets.SocketException)
        {
            // Closing is all that was asked; a port that fails to close is closed as far as this link goes.
        }

        static async Task ObserveAsync(ValueTask closing)
        {
            try
            {
                await closing.ConfigureAwait(false);
            }
            catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException or System.Net.Sockets.SocketException)
            {
            }
        }
    }
}
