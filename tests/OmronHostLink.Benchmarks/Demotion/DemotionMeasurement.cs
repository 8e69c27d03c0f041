using System.Diagnostics;
using System.Globalization;
using Microsoft.Extensions.Configuration;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Simulator;

namespace OmronHostLink.Benchmarks.Demotion;

/// <summary>
/// <c>demotion</c> mode: the gateway in process, polling two lines side by side, each 8 units on its own emulated 9600
/// bps serial-device server (both directions paced), one group of 10 words per unit every second. On the first line
/// every unit answers; on the second one of them (the last) is silent. The poll rate of the other units is counted on
/// both lines in two windows after the start (the first minute, while the silent unit is being found out, and the
/// next) and compared: both lines run at the same time, so a loaded machine slows both alike.
/// </summary>
internal static class DemotionMeasurement
{
    private const int Bits = 11;

    public static async Task<int> RunAsync(string[] args)
    {
        int units = 8;
        int baud = 9600;
        int words = 10;
        TimeSpan interval = TimeSpan.FromSeconds(1);
        TimeSpan window = TimeSpan.FromSeconds(60);
        var extra = new Dictionary<string, string?>(StringComparer.OrdinalIgnoreCase);
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--units":
                    units = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--baud":
                    baud = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--words":
                    words = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--interval":
                    interval = Duration.Parse(args[++i]);
                    break;
                case "--window":
                    window = Duration.Parse(args[++i]);
                    break;
                case "--set":
                    // A link key, for example --set Demotion:After=3
                    string[] kv = args[++i].Split('=', 2);
                    extra[kv[0]] = kv[1];
                    break;
                default:
                    Console.Error.WriteLine($"demotion: unknown argument {args[i]}");
                    return 2;
            }
        }

        double exchangeMs = (17 + 11 + (4 * words)) * Bits * 1000.0 / baud;
        Console.WriteLine($"# Demotion: {Environment.ProcessorCount} cores, {System.Runtime.InteropServices.RuntimeInformation.OSDescription}, {System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription}");
        Console.WriteLine($"# {units} units on one {baud} bps line (serial-device server, both directions paced, {Bits} bits/char), one group of {words} words per unit every {interval.TotalSeconds:0.###} s");
        Console.WriteLine($"# one read {exchangeMs:0.0} ms on the wire; the line is {exchangeMs * units / interval.TotalMilliseconds:P0} busy when every unit answers");
        Console.WriteLine($"# link settings: defaults{string.Concat(extra.Select(e => $", {e.Key}={e.Value}"))}; two windows of {window.TotalSeconds:0} s from the first poll");
        Console.WriteLine();

        int silent = units - 1;
        PollCounter[] lines = await MeasureAsync(units, [Enumerable.Range(0, units).ToArray(), Enumerable.Range(0, units - 1).ToArray()], baud, words, interval, window, extra);
        (double[] allFirst, double[] allSecond) = (lines[0].Rates(TimeSpan.Zero, window), lines[0].Rates(window, 2 * window));
        (double[] oneFirst, double[] oneSecond) = (lines[1].Rates(TimeSpan.Zero, window), lines[1].Rates(window, 2 * window));

        Console.WriteLine($"| Window | Polls/s of units 0–{silent - 1}, all {units} answer (each) | Polls/s of units 0–{silent - 1}, unit {silent} silent (each) | Silent ÷ all |");
        Console.WriteLine("|---|---|---|---|");
        Row($"0–{window.TotalSeconds:0} s", allFirst, oneFirst, silent);
        Row($"{window.TotalSeconds:0}–{2 * window.TotalSeconds:0} s", allSecond, oneSecond, silent);
        return 0;
    }

    private static void Row(string name, double[] all, double[] one, int healthy)
    {
        double a = all.Take(healthy).Average();
        double o = one.Take(healthy).Average();
        string each(double[] r) => string.Join(" ", r.Take(healthy).Select(x => x.ToString("0.00", CultureInfo.InvariantCulture)));
        Console.WriteLine($"| {name} | {a:0.000} ({each(all)}) | {o:0.000} ({each(one)}) | {o / a:P1} |");
    }

    /// <summary>Runs the gateway with one line per entry of <paramref name="answering"/> (the units that answer on it); the polls counted on each.</summary>
    private static async Task<PollCounter[]> MeasureAsync(int units, int[][] answering, int baud, int words, TimeSpan interval, TimeSpan window, Dictionary<string, string?> extra)
    {
        using var clock = new LineClock();
        var servers = new List<SerialDeviceServer>();
        var config = new Dictionary<string, string?>();
        for (int line = 0; line < answering.Length; line++)
        {
            var plc = new VirtualPlc(new VirtualPlcOptions { Units = answering[line] });
            SerialDeviceServer server = SerialDeviceServer.Start(plc, baud, Bits, clock);
            servers.Add(server);
            string link = $"HostLink:Links:line{line}:";
            config[link + "Tcp"] = $"127.0.0.1:{server.Port}";
            config[link + "Serial:BaudRate"] = baud.ToString(CultureInfo.InvariantCulture);
            foreach ((string key, string? value) in extra)
            {
                config[link + key] = value;
            }

            for (int u = 0; u < units; u++)
            {
                string g = $"{link}Groups:u{u}:";
                config[g + "Unit"] = u.ToString(CultureInfo.InvariantCulture);
                config[g + "Address"] = "D0";
                config[g + "Count"] = words.ToString(CultureInfo.InvariantCulture);
                config[g + "Interval"] = interval.ToString("c", CultureInfo.InvariantCulture);
                config[g + "Log"] = "OnChange";
            }
        }

        PollCounter[] counters = answering.Select(_ => new PollCounter(units)).ToArray();
        var counter = new LineCounters(counters);
        var configuration = new ConfigurationManager();
        configuration.AddInMemoryCollection(config);
        HostApplicationBuilder builder = GatewayHost.CreateBuilder(new HostApplicationBuilderSettings
        {
            DisableDefaults = true,
            EnvironmentName = "Production",
            ContentRootPath = AppContext.BaseDirectory,
            Configuration = configuration,
        });
        builder.Services.AddSingleton<ITagOutput>(counter);
        using IHost host = builder.Build();
        await host.StartAsync();
        await Task.Delay(2 * window + TimeSpan.FromSeconds(5));
        await host.StopAsync();
        foreach (SerialDeviceServer server in servers)
        {
            await server.DisposeAsync();
        }

        return counters;
    }

    /// <summary>Passes each line's polls to its counter (the links are named line0, line1…).</summary>
    private sealed class LineCounters(PollCounter[] counters) : ITagOutput
    {
        public void LinkOpened(string link, HostLinkUnit client)
        {
        }

        public void LinkChanged(string link, LinkState state, string? detail = null)
        {
        }

        public void TagChanged(TagChange change)
            => counters[int.Parse(change.Link.AsSpan(4), CultureInfo.InvariantCulture)].TagChanged(change);
    }

    /// <summary>Timestamps of every good poll of one line, by unit, from the line's first poll.</summary>
    private sealed class PollCounter(int units)
    {
        private readonly List<long>[] _polls = Enumerable.Range(0, units).Select(_ => new List<long>()).ToArray();
        private long _origin;

        public void TagChanged(TagChange change)
        {
            if (change.Quality != TagQuality.Good)
            {
                return;
            }

            long now = Stopwatch.GetTimestamp();
            lock (_polls)
            {
                if (_origin == 0)
                {
                    _origin = now;
                }

                _polls[change.Unit].Add(now);
            }
        }

        public double[] Rates(TimeSpan from, TimeSpan to)
        {
            lock (_polls)
            {
                long start = _origin + (long)(from.TotalSeconds * Stopwatch.Frequency);
                long end = _origin + (long)(to.TotalSeconds * Stopwatch.Frequency);
                return _polls.Select(p => p.Count(t => t >= start && t < end) / (to - from).TotalSeconds).ToArray();
            }
        }
    }
}
