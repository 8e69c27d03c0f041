using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Serves a <see cref="VirtualPlc"/> (or a <see cref="VirtualPlcLine"/> of them) over a serial line: a serial port or pseudo-terminal (one end of a socat pair) by
/// its name, or any stream from a factory.
/// </summary>
/// <remarks>
/// Given a port name, the host opens it with the package's <see cref="SerialTransport"/> (System.IO.Ports; a
/// pseudo-terminal in the 8-bit framing it holds, so a simulator restarted on the same pty opens it again) and keeps
/// serving it until stopped: when the device hangs up (socat restarted, an adapter unplugged) it closes the port and
/// opens the same name again as soon as it is back. Given a stream factory, it runs one session on the stream, and
/// <see cref="Completion"/> completes when that stream ends.
/// </remarks>
public sealed class SerialSimulatorHost : IAsyncDisposable
{
    private readonly Func<Stream, CancellationToken, Task> _serve;
    private readonly Func<Stream>? _open;
    private readonly SerialTransport? _transport;
    private readonly Action<string>? _report;
    private CancellationTokenSource? _stopping;
    private Task? _session;
    private Stream? _stream;

    /// <summary>Creates a host that runs one session on the stream <paramref name="openStream"/> returns.</summary>
    /// <param name="plc">The PLC to serve.</param>
    /// <param name="openStream">Opens the serial line; called by <see cref="StartAsync"/>.</param>
    public SerialSimulatorHost(VirtualPlc plc, Func<Stream> openStream)
    {
        ArgumentNullException.ThrowIfNull(plc);
        ArgumentNullException.ThrowIfNull(openStream);
        _serve = plc.RunAsync;
        _open = openStream;
    }

    /// <summary>Creates a host that serves a line of PLCs on the stream <paramref name="openStream"/> returns.</summary>
    /// <param name="line">The PLCs to serve, each with its own unit numbers.</param>
    /// <param name="openStream">Opens the serial line; called by <see cref="StartAsync"/>.</param>
    public SerialSimulatorHost(VirtualPlcLine line, Func<Stream> openStream)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(openStream);
        _serve = line.RunAsync;
        _open = openStream;
    }

    /// <summary>Creates a host that serves the serial port <paramref name="settings"/> names until it is stopped, reopening it after it was lost.</summary>
    /// <param name="plc">The PLC to serve.</param>
    /// <param name="settings">The port and its line settings.</param>
    /// <param name="report">Told, in a sentence, when the line is lost and when it is open again; may be null.</param>
    /// <exception cref="ArgumentException">A setting is not valid.</exception>
    public SerialSimulatorHost(VirtualPlc plc, SerialLineSettings settings, Action<string>? report = null)
        : this((plc ?? throw new ArgumentNullException(nameof(plc))).RunAsync, settings, report)
    {
    }

    /// <summary>Creates a host that serves a line of PLCs on the serial port <paramref name="settings"/> names until it is stopped, reopening it after it was lost.</summary>
    /// <param name="line">The PLCs to serve, each with its own unit numbers.</param>
    /// <param name="settings">The port and its line settings.</param>
    /// <param name="report">Told, in a sentence, when the line is lost and when it is open again; may be null.</param>
    /// <exception cref="ArgumentException">A setting is not valid.</exception>
    public SerialSimulatorHost(VirtualPlcLine line, SerialLineSettings settings, Action<string>? report = null)
        : this((line ?? throw new ArgumentNullException(nameof(line))).RunAsync, settings, report)
    {
    }

    /// <summary>Creates a host that serves a PLC answering as a capture recorded on the serial port <paramref name="settings"/> names, reopening it after it was lost.</summary>
    /// <param name="replay">The recorded PLC.</param>
    /// <param name="settings">The port and its line settings.</param>
    /// <param name="report">Told, in a sentence, when the line is lost and when it is open again; may be null.</param>
    /// <exception cref="ArgumentException">A setting is not valid.</exception>
    public SerialSimulatorHost(Replay.CaptureReplay replay, SerialLineSettings settings, Action<string>? report = null)
        : this((replay ?? throw new ArgumentNullException(nameof(replay))).RunAsync, settings, report)
    {
    }

    private SerialSimulatorHost(Func<Stream, CancellationToken, Task> serve, SerialLineSettings settings, Action<string>? report)
    {
        ArgumentNullException.ThrowIfNull(settings);
        _serve = serve;
        _transport = new SerialTransport(settings);
        _report = report;
        Description = settings.ToString();
    }

    /// <summary>The port and its settings ("/dev/ttyUSB0 9600 7E2"), or "stream".</summary>
    public string Description { get; } = "stream";

    /// <summary>How long to wait before opening a lost port again, and between attempts while it is missing. Default 200 ms.</summary>
    public TimeSpan ReopenInterval { get; init; } = TimeSpan.FromMilliseconds(200);

    /// <summary>How many times the port was opened again after it was lost.</summary>
    public int Reopened { get; private set; }

    /// <summary>A task that completes when the host stops serving: after <see cref="StopAsync"/>, or when a factory's stream ends.</summary>
    public Task Completion => _session ?? Task.CompletedTask;

    /// <summary>Opens the line and starts serving it.</summary>
    /// <param name="cancellationToken">Checked before the line is opened.</param>
    /// <returns>A completed task once the session runs.</returns>
    /// <exception cref="InvalidOperationException">The host is already started.</exception>
    /// <exception cref="HostLinkConnectionException">The serial port cannot be opened; the message names it and says why.</exception>
    public async Task StartAsync(CancellationToken cancellationToken = default)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (_session is not null)
        {
            throw new InvalidOperationException("The host is already started.");
        }

        _stopping = new CancellationTokenSource();
        if (_transport is not null)
        {
            Stream first = await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
            _session = ServeAsync(first, _stopping.Token);
        }
        else
        {
            _stream = _open!() ?? throw new InvalidOperationException("The stream factory returned null.");
            _session = _serve(_stream, _stopping.Token);
        }
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

        await _stopping!.CancelAsync().ConfigureAwait(false);
        try
        {
            await _session.WaitAsync(cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            if (_stream is not null)
            {
                await _stream.DisposeAsync().ConfigureAwait(false);
            }

            if (_transport is not null)
            {
                await _transport.CloseAsync().ConfigureAwait(false);
            }

            _stopping.Dispose();
            _stopping = null;
            _stream = null;
            _session = null;
        }
    }

    /// <summary>Stops the host.</summary>
    /// <returns>A task that completes when the host has stopped.</returns>
    public async ValueTask DisposeAsync()
    {
        await StopAsync().ConfigureAwait(false);
        if (_transport is not null)
        {
            await _transport.DisposeAsync().ConfigureAwait(false);
        }
    }

    private async Task ServeAsync(Stream stream, CancellationToken stop)
    {
        SerialTransport transport = _transport!;
        while (true)
        {
            await _serve(stream, stop).ConfigureAwait(false);
            await transport.CloseAsync().ConfigureAwait(false);
            if (stop.IsCancellationRequested)
            {
                return;
            }

            _report?.Invoke($"Lost {Description}; opening it again when it is back.");
            Stream? again = await ReopenAsync(transport, stop).ConfigureAwait(false);
            if (again is null)
            {
                return;
            }

            stream = again;
            Reopened++;
            _report?.Invoke($"Serving {Description} again.");
        }
    }

    /// <summary>Opens the lost port again, retrying while it is missing; null when the host stops first.</summary>
    private async Task<Stream?> ReopenAsync(SerialTransport transport, CancellationToken stop)
    {
        while (true)
        {
            try
            {
                await Task.Delay(ReopenInterval, stop).ConfigureAwait(false);
                return await transport.OpenAsync(stop).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (stop.IsCancellationRequested)
            {
                return null;
            }
            catch (HostLinkConnectionException)
            {
                // Not back yet.
            }
        }
    }
}
