using System.Diagnostics;
using System.Globalization;
using System.IO.Ports;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// <c>serial</c> mode: word reads over a real pseudo-terminal pair (socat) against the simulator, which paces its
/// answers at the line's speed; in one run, side by side, the client on its System.IO.Ports transport and a minimal
/// loop on <see cref="SerialPort.BaseStream"/> (write the RD frame, read to CR, no checks).
/// </summary>
/// <remarks>
/// The variants take turns on the same pty and simulator: each round opens one variant's port, warms it up, times
/// its reads, and closes it before the next variant opens (two readers on one pty would steal each other's bytes).
/// The order of the variants rotates from round to round.
/// </remarks>
internal static class SerialEfficiency
{
    private const int Bits = 11;
    private const int WarmUp = 5;

    private delegate Task<Func<int, Task>> Opener(string port, int baud, Stack<IAsyncDisposable> cleanup);

    public static async Task<int> RunAsync(string[] args)
    {
        int rounds = 5;
        int reads = 20;
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--rounds":
                    rounds = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--reads":
                    reads = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
            }
        }

        (string Name, Opener Open)[] variants =
        [
            ("ours: ReadWordsAsync, System.IO.Ports transport", OpenOursAsync),
            ("minimal loop on SerialPort.BaseStream", OpenMinimalAsync),
        ];

        Console.WriteLine($"# Serial: {Environment.ProcessorCount} cores, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}, {System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
        Console.WriteLine($"# socat pty pair; simulator paces its answers at the baud rate (11 bits/char), turnaround 0; {rounds} rounds × {reads} reads per variant and size; ms per read");
        Console.WriteLine();
        Console.WriteLine("| Line | Words | Answer on the wire ms | Variant | Median ms | p10–p90 ms | Ours ÷ variant, time (ours' speed as % of it) |");
        Console.WriteLine("|---|---|---|---|---|---|---|");
        foreach (int baud in new[] { 9600, 115200 })
        {
            await using SocatPtyPair pty = await SocatPtyPair.StartAsync();
            var plc = new VirtualPlc(new VirtualPlcOptions { BaudRate = baud, BitsPerCharacter = Bits });
            for (int i = 0; i < 100; i++)
            {
                plc.WriteWord(PlcArea.Dm, i, (ushort)(i * 3));
            }

            await using var host = new SerialSimulatorHost(plc, new SerialLineSettings { PortName = pty.PathB, BaudRate = baud });
            await host.StartAsync();

            int[] sizes = [1, 30];
            var samples = new List<double>[variants.Length, sizes.Length];
            for (int v = 0; v < variants.Length; v++)
            {
                for (int s = 0; s < sizes.Length; s++)
                {
                    samples[v, s] = [];
                }
            }

            for (int round = 0; round < rounds; round++)
            {
                for (int k = 0; k < variants.Length; k++)
                {
                    int v = (k + round) % variants.Length;
                    var cleanup = new Stack<IAsyncDisposable>();
                    try
                    {
                        Func<int, Task> read = await variants[v].Open(pty.PathA, baud, cleanup);
                        for (int s = 0; s < sizes.Length; s++)
                        {
                            for (int w = 0; w < WarmUp; w++)
                            {
                                await read(sizes[s]);
                            }

                            for (int r = 0; r < reads; r++)
                            {
                                long start = Stopwatch.GetTimestamp();
                                await read(sizes[s]);
                                samples[v, s].Add(Stopwatch.GetElapsedTime(start).TotalMilliseconds);
                            }
                        }
                    }
                    finally
                    {
                        while (cleanup.TryPop(out IAsyncDisposable? d))
                        {
                            await d.DisposeAsync();
                        }
                    }
                }
            }

            for (int s = 0; s < sizes.Length; s++)
            {
                double wire = AnswerCharacters(sizes[s]) * Bits * 1000.0 / baud;
                double ours = Percentile(samples[0, s], 0.5);
                for (int v = 0; v < variants.Length; v++)
                {
                    double median = Percentile(samples[v, s], 0.5);
                    string ratio = v == 0 ? "—" : $"{ours / median:0.000} ({median / ours:P1})";
                    Console.WriteLine($"| {baud} 7E2 | {sizes[s]} | {wire:0.00} | {variants[v].Name} | {median:0.00} | {Percentile(samples[v, s], 0.1):0.00}–{Percentile(samples[v, s], 0.9):0.00} | {ratio} |");
                }
            }
        }

        return 0;
    }

    /// <summary>Characters of the one-frame RD answer: @, unit, header, end code, 4 per word, FCS, *, CR.</summary>
    private static int AnswerCharacters(int words) => 11 + (4 * words);

    private static double Percentile(List<double> values, double p)
    {
        var sorted = values.Order().ToArray();
        return sorted[(int)Math.Min(sorted.Length - 1, Math.Round(p * (sorted.Length - 1)))];
    }

    private static Task<Func<int, Task>> OpenOursAsync(string port, int baud, Stack<IAsyncDisposable> cleanup)
    {
        HostLinkClient client = HostLinkClient.ForSerialPort(
            new SerialLineSettings { PortName = port, BaudRate = baud },
            new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromMilliseconds(200) });
        cleanup.Push(client);
        return Task.FromResult<Func<int, Task>>(words => client.ReadWordsAsync("D0", words));
    }

    private static Task<Func<int, Task>> OpenMinimalAsync(string port, int baud, Stack<IAsyncDisposable> cleanup)
    {
        // A pty holds 8 data bits and no parity (and may refuse 7E2 once its first user has closed it).
        var serial = new SerialPort(port, baud, Parity.None, 8, StopBits.Two);
        serial.Open();
        cleanup.Push(new Disposer(serial.Dispose));
        Stream stream = serial.BaseStream;
        var frames = new Dictionary<int, byte[]>();
        var buffer = new byte[512];
        return Task.FromResult<Func<int, Task>>(async words =>
        {
            if (!frames.TryGetValue(words, out byte[]? frame))
            {
                frame = new byte[AreaReadCommand.GetFrameLength(CModeArea.Dm)];
                AreaReadCommand.WriteFrame(0, CModeArea.Dm, 0, words, 0, frame);
                frames[words] = frame;
            }

            await stream.WriteAsync(frame);
            while (true)
            {
                int n = await stream.ReadAsync(buffer);
                if (n == 0 || Array.IndexOf(buffer, (byte)'\r', 0, n) >= 0)
                {
                    return;
                }
            }
        });
    }

    private sealed class Disposer(Action dispose) : IAsyncDisposable
    {
        public ValueTask DisposeAsync()
        {
            dispose();
            return default;
        }
    }
}
