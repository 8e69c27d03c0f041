using System.Net;
using System.Net.Sockets;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// An emulated serial-device server on 127.0.0.1: a TCP port whose far side is a serial line at a given baud rate
/// with a <see cref="VirtualPlc"/> on it. Like the simulator's TCP host, one Host Link session per connection on the
/// same memory; unlike it, both directions of the line are paced (<see cref="PacedSerialStream"/>), as a real server
/// delivers the host's command at the line's speed too.
/// </summary>
internal sealed class SerialDeviceServer : IAsyncDisposable
{
    private readonly TcpListener _listener = new(IPAddress.Loopback, 0);
    private readonly CancellationTokenSource _stop = new();
    private readonly List<Task> _sessions = new();
    private readonly List<PacedSerialStream> _lines = new();
    private readonly int _baudRate;
    private readonly int _bitsPerCharacter;
    private readonly LineClock _clock;
    private readonly Func<Stream, Stream>? _plcSide;
    private Task _acceptLoop = Task.CompletedTask;

    private SerialDeviceServer(VirtualPlc plc, int baudRate, int bitsPerCharacter, LineClock clock, Func<Stream, Stream>? plcSide)
    {
        _plcSide = plcSide;
        Plc = plc;
        _clock = clock;
        _baudRate = baudRate;
        _bitsPerCharacter = bitsPerCharacter;
    }

    /// <summary>The PLC on the line.</summary>
    public VirtualPlc Plc { get; }

    /// <summary>The TCP port on 127.0.0.1.</summary>
    public int Port => ((IPEndPoint)_listener.LocalEndpoint).Port;

    /// <summary>Connections accepted so far.</summary>
    public int Connections { get; private set; }

    /// <summary>Characters on the line both ways, over every connection so far.</summary>
    public long LineCharacters
    {
        get
        {
            lock (_lines)
            {
                return _lines.Sum(l => l.CharactersIn + l.CharactersOut);
            }
        }
    }

    /// <summary>The pacing samples of every connection since the last call (see <see cref="PacedSerialStream.TakeSamples"/>).</summary>
    public (double[] GapsMs, double[] LatenessMs) TakeSamples()
    {
        lock (_lines)
        {
            var taken = _lines.Select(l => l.TakeSamples()).ToArray();
            return (taken.SelectMany(t => t.GapsMs).ToArray(), taken.SelectMany(t => t.LatenessMs).ToArray());
        }
    }

    /// <summary>Answer frames the PLC has sent (one per single-frame transaction): the simulator's own counter.</summary>
    public long AnswerFrames => Plc.FaultCounters.Frames;

    /// <summary>Starts listening on a free loopback port; <paramref name="plcSide"/> wraps the line at the PLC's end (to watch it), or is null.</summary>
    public static SerialDeviceServer Start(VirtualPlc plc, int baudRate, int bitsPerCharacter, LineClock clock, Func<Stream, Stream>? plcSide = null)
    {
        var server = new SerialDeviceServer(plc, baudRate, bitsPerCharacter, clock, plcSide);
        server._listener.Start();
        server._acceptLoop = server.AcceptLoopAsync();
        return server;
    }

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        _listener.Stop();
        Task[] pending;
        lock (_sessions)
        {
            pending = [.. _sessions, _acceptLoop];
        }

        await Task.WhenAll(pending).WaitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        _stop.Dispose();
    }

    private async Task AcceptLoopAsync()
    {
        while (!_stop.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await _listener.AcceptTcpClientAsync(_stop.Token).ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }

            client.NoDelay = true;
            Connections++;
            var line = new PacedSerialStream(client.GetStream(), _baudRate, _bitsPerCharacter, _clock);
            lock (_lines)
            {
                _lines.Add(line);
            }

            lock (_sessions)
            {
                _sessions.RemoveAll(t => t.IsCompleted);
                _sessions.Add(ServeAsync(client, line));
            }
        }
    }

    private async Task ServeAsync(TcpClient client, PacedSerialStream line)
    {
        await Task.Yield();
        using (client)
        {
            await using (line.ConfigureAwait(false))
            {
                await Plc.RunAsync(_plcSide?.Invoke(line) ?? line, _stop.Token).ConfigureAwait(false);
            }
        }
    }
}
