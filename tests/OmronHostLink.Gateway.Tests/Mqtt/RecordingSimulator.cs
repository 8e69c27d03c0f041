using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;
using OmronHostLink.Simulator;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// A <see cref="VirtualPlc"/> served over TCP on 127.0.0.1 that logs every frame it receives and every frame it sends:
/// the tests read from it what reached the PLC and what it answered, and drive memory changes in step with the worker's
/// polls.
/// </summary>
public sealed class RecordingSimulator : IAsyncDisposable
{
    private readonly List<string> _received = new();
    private readonly List<string> _sent = new();
    private readonly object _gate = new();
    private readonly List<(TcpClient Client, Task Session)> _sessions = new();
    private TcpListener? _listener;
    private CancellationTokenSource? _stopping;
    private Task? _accepting;
    private readonly Func<Stream, CancellationToken, Task> _serve;
    private long _answers;

    private RecordingSimulator(VirtualPlc plc, Func<Stream, CancellationToken, Task> serve)
    {
        Plc = plc;
        _serve = serve;
    }

    /// <summary>The PLC (the first of a line's).</summary>
    public VirtualPlc Plc { get; }

    /// <summary>The port on 127.0.0.1.</summary>
    public int Port { get; private set; }

    /// <summary>Every frame received, without its CR, in order.</summary>
    public IReadOnlyList<string> Received
    {
        get
        {
            lock (_received)
            {
                return _received.ToArray();
            }
        }
    }

    /// <summary>Every frame sent (answers, and the bare CR asking for a command's next frame), without its CR, in order.</summary>
    public IReadOnlyList<string> Sent
    {
        get
        {
            lock (_sent)
            {
                return _sent.ToArray();
            }
        }
    }

    /// <summary>Answer frames sent so far.</summary>
    public long Answers => Interlocked.Read(ref _answers);

    /// <summary>Starts a simulator on a free port (or <paramref name="port"/>).</summary>
    public static async Task<RecordingSimulator> StartAsync(VirtualPlc plc, int port = 0)
    {
        var simulator = new RecordingSimulator(plc, plc.RunAsync);
        await simulator.RestartAsync(port);
        return simulator;
    }

    /// <summary>Starts a simulator of a multidrop line (each unit answered by its own PLC) on a free port.</summary>
    public static async Task<RecordingSimulator> StartAsync(VirtualPlcLine line)
    {
        var simulator = new RecordingSimulator(line.Plcs[0], line.RunAsync);
        await simulator.RestartAsync(0);
        return simulator;
    }

    /// <summary>The C-mode header of a frame (<c>RD</c>, <c>WD</c>, <c>FA</c>…): the two characters after <c>@</c> and the unit.</summary>
    public static string Header(string frame) => frame.Length >= 5 && frame[0] == '@' ? frame.Substring(3, 2) : "";

    /// <summary>Listens again (after <see cref="StopAsync"/>) on <paramref name="port"/>, or the port it had.</summary>
    public Task RestartAsync(int port = 0)
    {
        var listener = new TcpListener(IPAddress.Loopback, port == 0 ? Port : port);
        listener.Start();
        _listener = listener;
        Port = ((IPEndPoint)listener.LocalEndpoint).Port;
        _stopping = new CancellationTokenSource();
        _accepting = AcceptAsync(listener, _stopping.Token);
        return Task.CompletedTask;
    }

    /// <summary>Stops listening and closes every connection (the PLC "goes away").</summary>
    public async Task StopAsync()
    {
        if (_listener is null)
        {
            return;
        }

        await _stopping!.CancelAsync();
        _listener.Stop();
        _listener = null;
        await _accepting!.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        (TcpClient Client, Task Session)[] sessions;
        lock (_gate)
        {
            sessions = _sessions.ToArray();
            _sessions.Clear();
        }

        foreach ((TcpClient client, Task session) in sessions)
        {
            client.Dispose();
            await session.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }

        _stopping.Dispose();
    }

    /// <summary>
    /// Waits until the PLC has sent <paramref name="count"/> more answers than <paramref name="since"/>. Two answers
    /// after a memory change mean a poll has read the new value: the second request was sent after the first answer,
    /// which came after the change.
    /// </summary>
    public async Task WaitForAnswersAsync(long since, int count, TimeSpan? patience = null)
    {
        TimeSpan limit = patience ?? TimeSpan.FromSeconds(10);
        await Eventually.UntilAsync(() => Answers >= since + count, $"the PLC sends {count} answers", () => $"It sent {Answers - since}.", limit);
    }

    /// <inheritdoc/>
    public async ValueTask DisposeAsync() => await StopAsync();

    private async Task AcceptAsync(TcpListener listener, CancellationToken cancellationToken)
    {
        while (!cancellationToken.IsCancellationRequested)
        {
            TcpClient client;
            try
            {
                client = await listener.AcceptTcpClientAsync(cancellationToken);
            }
            catch (Exception e) when (e is OperationCanceledException or SocketException or ObjectDisposedException)
            {
                return;
            }

            client.NoDelay = true;
            var stream = new RecordingStream(client.GetStream(), this);
            Task session = _serve(stream, cancellationToken);
            lock (_gate)
            {
                _sessions.Add((client, session));
            }
        }
    }

    /// <summary>Passes bytes through, cutting what the PLC reads and writes into frames at CR and counting the CRs it writes.</summary>
    private sealed class RecordingStream(NetworkStream inner, RecordingSimulator owner) : PassThroughStream(inner)
    {
        private readonly StringBuilder _frame = new();
        private readonly StringBuilder _answer = new();

        public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            int n = await Inner.ReadAsync(buffer, cancellationToken);
            return Seen(buffer.Span.Slice(0, n));
        }

        public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            await Inner.WriteAsync(buffer, cancellationToken);
            Sent(buffer.Span);
        }

        private int Seen(ReadOnlySpan<byte> bytes)
        {
            foreach (byte b in bytes)
            {
                if (b == '\r')
                {
                    lock (owner._received)
                    {
                        owner._received.Add(_frame.ToString());
                    }

                    _frame.Clear();
                }
                else
                {
                    _frame.Append((char)b);
                }
            }

            return bytes.Length;
        }

        private void Sent(ReadOnlySpan<byte> bytes)
        {
            foreach (byte b in bytes)
            {
                if (b == '\r')
                {
                    lock (owner._sent)
                    {
                        owner._sent.Add(_answer.ToString());
                    }

                    _answer.Clear();
                    Interlocked.Increment(ref owner._answers);
                }
                else
                {
                    _answer.Append((char)b);
                }
            }
        }
    }
}
