using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using OmronHostLink.Transports;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// <c>wire</c> mode, TCP table: <see cref="HostLinkClient.ReadWordsAsync(string, int, CancellationToken)"/> side by
/// side with a minimal blocking client (send the RD frame, read to CR) against the same wire-paced simulator over TCP
/// loopback, transactions interleaved one by one so both see the same machine load. The ratio is the client's speed
/// relative to the minimal one: what the link's deadlines, pump, pipe and validation cost per transaction.
/// </summary>
internal static class MinimalClientComparison
{
    private const int Bits = 11;

    public static async Task RunAsync(int transactions)
    {
        Console.WriteLine();
        Console.WriteLine($"## Client vs. a minimal blocking client, TCP loopback, wire-paced simulator (median of {transactions} interleaved transactions each)");
        Console.WriteLine();
        Console.WriteLine("| Line | Words | Answer wire time ms | Minimal client ms (median) | HostLinkClient ms (median) | Client speed / minimal |");
        Console.WriteLine("|---|---|---|---|---|---|");
        foreach (int baud in new[] { 115200 })
        {
            foreach (int words in new[] { 1, 30 })
            {
                (double minimal, double client, double theoretical) = await MeasureAsync(baud, words, transactions);
                Console.WriteLine($"| {baud} 7E2 | {words} | {theoretical:0.00} | {minimal:0.000} | {client:0.000} | {minimal / client:P1} |");
            }
        }
    }

    private static async Task<(double Minimal, double Client, double Theoretical)> MeasureAsync(int baud, int words, int transactions)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { BaudRate = baud, BitsPerCharacter = Bits });
        await using var host = new TcpSimulatorHost(plc);
        await host.StartAsync();
        IPEndPoint endPoint = host.EndPoint;

        await using HostLinkClient client = HostLinkClient.ForTcp(endPoint.Address.ToString(), endPoint.Port, new HostLinkClientOptions
        {
            LineTiming = new LineTiming(baud, Bits),
            TurnaroundAllowance = TimeSpan.FromMilliseconds(200),
        });
        using var minimal = new MinimalClient(endPoint, words);

        for (int i = 0; i < 20; i++)
        {
            await client.ReadWordsAsync("D0", words);
            await minimal.TimeReadAsync();
        }

        var clientTimes = new double[transactions];
        var minimalTimes = new double[transactions];
        for (int i = 0; i < transactions; i++)
        {
            long start = Stopwatch.GetTimestamp();
            await client.ReadWordsAsync("D0", words);
            clientTimes[i] = Stopwatch.GetElapsedTime(start).TotalMilliseconds;

            minimalTimes[i] = await minimal.TimeReadAsync();
        }

        Array.Sort(clientTimes);
        Array.Sort(minimalTimes);
        // Over TCP only the simulator's answer is paced; the command arrives at once.
        double theoretical = (minimal.AnswerCharacters * Bits * 1000.0) / baud;
        return (minimalTimes[transactions / 2], clientTimes[transactions / 2], theoretical);
    }

    /// <summary>
    /// The least a host can do: one blocking socket, the command frame written, bytes read until CR, on a thread of its
    /// own (blocking a pool thread would slow the simulator sharing the pool, not the minimal client).
    /// </summary>
    private sealed class MinimalClient : IDisposable
    {
        private readonly Socket _socket;
        private readonly Thread _thread;
        private readonly SemaphoreSlim _go = new(0);
        private TaskCompletionSource<double>? _done;
        private volatile bool _stopping;
        private readonly byte[] _command = new byte[32];
        private readonly int _commandLength;
        private readonly byte[] _answer = new byte[256];

        public MinimalClient(IPEndPoint endPoint, int words)
        {
            _socket = new Socket(endPoint.AddressFamily, SocketType.Stream, ProtocolType.Tcp) { NoDelay = true };
            _socket.Connect(endPoint);
            _commandLength = AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, words, 0, _command);
            _thread = new Thread(Run) { IsBackground = true, Name = "minimal client" };
            _thread.Start();
        }

        /// <summary>Characters of the answer, known after the first read.</summary>
        public int AnswerCharacters { get; private set; }

        /// <summary>One read on the client's thread; its duration in milliseconds, timed there.</summary>
        public Task<double> TimeReadAsync()
        {
            _done = new TaskCompletionSource<double>(TaskCreationOptions.RunContinuationsAsynchronously);
            _go.Release();
            return _done.Task;
        }

        private void Run()
        {
            while (true)
            {
                _go.Wait();
                if (_stopping)
                {
                    return;
                }

                try
                {
                    long start = Stopwatch.GetTimestamp();
                    Read();
                    _done!.SetResult(Stopwatch.GetElapsedTime(start).TotalMilliseconds);
                }
                catch (Exception e)
                {
                    _done!.SetException(e);
                }
            }
        }

        private void Read()
        {
            _socket.Send(_command.AsSpan(0, _commandLength));
            int length = 0;
            while (length == 0 || _answer[length - 1] != (byte)'\r')
            {
                int n = _socket.Receive(_answer.AsSpan(length));
                if (n == 0)
                {
                    throw new IOException("The simulator closed the connection.");
                }

                length += n;
            }

            // End code 00 at text offset 5-6: anything else means the comparison is not like for like.
            if (_answer[5] != (byte)'0' || _answer[6] != (byte)'0')
            {
                throw new InvalidOperationException("The minimal client's read was refused.");
            }

            AnswerCharacters = length;
        }

        public void Dispose()
        {
            _stopping = true;
            _go.Release();
            _thread.Join();
            _socket.Dispose();
            _go.Dispose();
        }
    }
}
