using System.Net;
using System.Net.Sockets;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// Serves a <see cref="VirtualPlc"/> (or a <see cref="VirtualPlcLine"/> of several) over TCP, as a serial device server
/// would: one Host Link session per accepted connection, all on the same PLC memory. Listens on 127.0.0.1 unless another
/// address is passed explicitly.
/// </summary>
public sealed class TcpSimulatorHost : IAsyncDisposable
{
    private readonly Func<Stream, CancellationToken, Task> _serve;
    private readonly IPEndPoint _requested;
    private readonly object _gate = new();
    private readonly HashSet<Task> _sessions = new();
    private int _activeSessions;
    private TcpListener? _listener;
    private CancellationTokenSource? _stopping;
    private Task? _acceptLoop;

    /// <summary>Creates the host; it listens once started.</summary>
    /// <param name="plc">The PLC to serve.</param>
    /// <param name="endPoint">Where to listen; null for 127.0.0.1 on an ephemeral port. Port 0 picks an ephemeral port.</param>
    public TcpSimulatorHost(VirtualPlc plc, IPEndPoint? endPoint = null)
    {
        ArgumentNullException.ThrowIfNull(plc);
        _serve = plc.RunAsync;
        _requested = endPoint ?? new IPEndPoint(IPAddress.Loopback, 0);
    }

    /// <summary>Creates the host of a line of PLCs; it listens once started.</summary>
    /// <param name="line">The PLCs to serve, each with its own unit numbers.</param>
    /// <param name="endPoint">Where to listen; null for 127.0.0.1 on an ephemeral port. Port 0 picks an ephemeral port.</param>
    public TcpSimulatorHost(VirtualPlcLine line, IPEndPoint? endPoint = null)
    {
        ArgumentNullException.ThrowIfNull(line);
        _serve = line.RunAsync;
        _requested = endPoint ?? new IPEndPoint(IPAddress.Loopback, 0);
    }

    /// <summary>Creates the host of a PLC that answers as a capture recorded; it listens once started.</summary>
    /// <param name="replay">The recorded PLC.</param>
    /// <param name="endPoint">Where to listen; null for 127.0.0.1 on an ephemeral port. Port 0 picks an ephemeral port.</param>
    public TcpSimulatorHost(Replay.CaptureReplay replay, IPEndPoint? endPoint = null)
    {
        ArgumentNullException.ThrowIfNull(replay);
        _serve = replay.RunAsync;
        _requested = endPoint ?? new IPEndPoint(IPAddress.Loopback, 0);
    }

    /// <summary>The bound end point (the actual port when port 0 was asked for); the requested one before <see cref="StartAsync"/>.</summary>
    public IPEndPoint EndPoint => _listener?.LocalEndpoint as IPEndPoint ?? _requested;

    /// <summary>The number of connections being served now.</summary>
    /// <remarks>
    /// Counted by the sessions themselves, so a session has left the count when its task completes (and so when
    /// <see cref="StopAsync"/> returns); the set of session tasks is tidied up by a continuation that may run later.
    /// </remarks>
    public int ActiveSessions => Volatile.Read(ref _activeSessions);

    /// <summary>The number of connections accepted since start.</summary>
    public int AcceptedConnections { get; private set; }

    /// <summary>Starts listening and accepting connections.</summary>
    /// <param name="cancellationToken">Not used beyond an early check; the host runs until <see cref="StopAsync"/>.</param>
    /// <returns>A completed task once the socket listens.</returns>
    /// <exception cref="InvalidOperationException">The host is already started.</exception>
    /// <exception cref="SocketException">The end point cannot be bound.</exception>
    public Task StartAsync(CancellationToken cancellationToken = default)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (_listener is not null)
        {
            throw new InvalidOperationException("The host is already started.");
        }

        var listener = new TcpListener(_requested);
        listener.Start();
        _listener = listener;
        _stopping = new CancellationTokenSource();
        _acceptLoop = AcceptLoopAsync(listener, _stopping.Token);
        return Task.CompletedTask;
    }

    /// <summary>Stops listening, closes every connection and waits for the sessions to end.</summary>
    /// <param name="cancellationToken">Stops waiting for the sessions.</param>
    /// <returns>A task that completes when the host has stopped.</returns>
    public async Task StopAsync(CancellationToken cancellationToken = default)
    {
        TcpListener? listener = _listener;
        if (listener is null)
        {
            return;
        }

        _stopping!.Cancel();
        listener.Stop();
        Task[] pending;
        lock (_gate)
        {
            pending = [.. _sessions, _acceptLoop!];
        }

        await Task.WhenAll(pending).WaitAsync(cancellationToken).ConfigureAwait(false);
        _stopping.Dispose();
        _stopping = null;
        _listener = null;
    }

    /// <summary>Stops the host.</summary>
    /// <returns>A task that completes when the host has stopped.</returns>
    public async ValueTask DisposeAsync() => await StopAsync().ConfigureAwait(false);

    private async Task AcceptLoopAsync(TcpListener listener, CancellationToken stopping)
    {
        while (!stopping.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await listener.AcceptTcpClientAsync(stopping).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }

            client.NoDelay = true;
            AcceptedConnections++;
            Interlocked.Increment(ref _activeSessions);
            Task session = ServeAsync(client, stopping);
            lock (_gate)
            {
                _sessions.Add(session);
            }

            _ = session.ContinueWith(
                t =>
                {
                    lock (_gate)
                    {
                        _sessions.Remove(t);
                    }
                },
                CancellationToken.None,
                TaskContinuationOptions.ExecuteSynchronously,
                TaskScheduler.Default);
        }
    }

    private async Task ServeAsync(TcpClient client, CancellationToken stopping)
    {
        try
        {
            await Task.Yield();
            using (client)
            {
                NetworkStream stream = client.GetStream();
                await using (stream.ConfigureAwait(false))
                {
                    await _serve(stream, stopping).ConfigureAwait(false);
                }
            }
        }
        finally
        {
            Interlocked.Decrement(ref _activeSessions);
        }
    }
}
