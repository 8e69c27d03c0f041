namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Serves a <see cref="VirtualPlc"/> over a serial line: opens the stream (for example a serial port or one end of a
/// pty pair made by socat), runs one Host Link session on it until it ends or the host stops, and closes it.
/// </summary>
/// <remarks>
/// The stream comes from a factory so that any transport fits: a <c>System.IO.Ports.SerialPort.BaseStream</c>, the
/// package's serial transport, or a <see cref="FileStream"/> on a pty.
/// </remarks>
public sealed class SerialSimulatorHost : IAsyncDisposable
{
    private readonly Func<Stream, CancellationToken, Task> _serve;
    private readonly Func<Stream> _open;
    private CancellationTokenSource? _stopping;
    private Task? _session;
    private Stream? _stream;

    /// <summary>Creates the host.</summary>
    /// <param name="plc">The PLC to serve.</param>
    /// <param name="openStream">Opens the serial line; called by <see cref="StartAsync"/>.</param>
    public SerialSimulatorHost(VirtualPlc plc, Func<Stream> openStream)
    {
        ArgumentNullException.ThrowIfNull(plc);
        ArgumentNullException.ThrowIfNull(openStream);
        _serve = plc.RunAsync;
        _open = openStream;
    }

    /// <summary>Creates the host of a line of PLCs.</summary>
    /// <param name="line">The PLCs to serve, each with its own unit numbers.</param>
    /// <param name="openStream">Opens the serial line; called by <see cref="StartAsync"/>.</param>
    public SerialSimulatorHost(VirtualPlcLine line, Func<Stream> openStream)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(openStream);
        _serve = line.RunAsync;
        _open = openStream;
    }

    /// <summary>A task that completes when the session ends (the line closed, or <see cref="StopAsync"/>).</summary>
    public Task Completion => _session ?? Task.CompletedTask;

    /// <summary>Opens the line and starts the session.</summary>
    /// <param name="cancellationToken">Checked before the line is opened.</param>
    /// <returns>A completed task once the session runs.</returns>
    /// <exception cref="InvalidOperationException">The host is already started.</exception>
    public Task StartAsync(CancellationToken cancellationToken = default)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (_session is not null)
        {
            throw new InvalidOperationException("The host is already started.");
        }

        _stream = _open() ?? throw new InvalidOperationException("The stream factory returned null.");
        _stopping = new CancellationTokenSource();
        _session = _serve(_stream, _stopping.Token);
        return Task.CompletedTask;
    }

    /// <summary>Ends the session and closes the line.</summary>
    /// <param name="cancellationToken">Stops waiting for the session to end.</param>
    /// <returns>A task that completes when the host has stopped.</returns>
    public async Task StopAsync(CancellationToken cancellationToken = default)
    {
        if (_session is null)
        {
            return;
        }

        _stopping!.Cancel();
        try
        {
            await _session.WaitAsync(cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            await _stream!.DisposeAsync().ConfigureAwait(false);
            _stopping.Dispose();
            _stopping = null;
            _stream = null;
            _session = null;
        }
    }

    /// <summary>Stops the host.</summary>
    /// <returns>A task that completes when the host has stopped.</returns>
    public async ValueTask DisposeAsync() => await StopAsync().ConfigureAwait(false);
}
