using System.Diagnostics;
using System.Globalization;
using System.Net;
using System.Text.Json.Nodes;
using OmronHostLink.Benchmarks.Scale;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Benchmarks.Status;

/// <summary>
/// What the status page costs the gateway: the gateway (a separate process) polls N tags of one word each over several
/// links to a simulator in this process, and its CPU time is measured over a window in three states, in turn, each on a
/// fresh gateway — no <c>Status</c> section; the page on with no browser; the page on with B headless Chromium browsers
/// open on its Tags view (the view that sends the most: every tag at each refresh). Medians over the rounds; 100 % is
/// one core. The simulator's answers over the window show the polling was the same in every state.
/// </summary>
/// <remarks>
/// <c>dotnet run -c Release --project tests/OmronHostLink.Benchmarks -- status [--tags 1000] [--links 4] [--interval 1s]
/// [--seconds 60] [--warmup 20] [--rounds 3] [--browsers 3]</c>. Needs Linux (/proc) and Debian's chromium.
/// </remarks>
internal static class StatusPageMeasurement
{
    private const string Chromium = "/usr/bin/chromium";

    public static async Task<int> RunAsync(string[] args)
    {
        int tags = Option(args, "--tags", 1000);
        int links = Option(args, "--links", 4);
        int seconds = Option(args, "--seconds", 60);
        int warmup = Option(args, "--warmup", 20);
        int rounds = Option(args, "--rounds", 3);
        int browsers = Option(args, "--browsers", 3);
        TimeSpan interval = Duration.Parse(Text(args, "--interval") ?? "1s");
        string worker = WorkerProcess.Locate(Text(args, "--worker"));

        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0], Turnaround = TimeSpan.FromMilliseconds(1) });
        await using var simulator = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, 0));
        await simulator.StartAsync();
        using var animate = new CancellationTokenSource();
        Task changing = ChangeAsync(plc, tags, animate.Token);

        Console.WriteLine($"# Status page cost: {tags} tags (one word each) on {links} link(s) every {interval.TotalSeconds} s, a {seconds} s window after {warmup} s, {rounds} round(s), {browsers} browser(s); load average {ProcessSample.LoadAverage():0.0} on {Environment.ProcessorCount} cores");
        Console.WriteLine("| Round | State | Gateway CPU % (one core) | Answers in the window | CPU ms per 1,000 answers | Page connections |");
        Console.WriteLine("|---|---|---|---|---|---|");
        var results = new Dictionary<string, List<double>>();
        string[] states = ["off", "on, no browser", $"on, {browsers} browsers on Tags"];
        for (int round = 1; round <= rounds; round++)
        {
            foreach (string state in states)
            {
                int port = FreePort();
                bool page = state != "off";
                await using WorkerProcess gateway = await WorkerProcess.StartAsync(worker, Settings(simulator.EndPoint.Port, tags, links, interval, page ? port : null), CancellationToken.None);
                var chromiums = new List<Process>();
                try
                {
                    if (state.Contains("browsers", StringComparison.Ordinal))
                    {
                        await WaitForPortAsync(port, gateway);
                        for (int b = 0; b < browsers; b++)
                        {
                            chromiums.Add(StartBrowser($"http://127.0.0.1:{port}/#tags"));
                        }
                    }

                    await Task.Delay(TimeSpan.FromSeconds(warmup));
                    int connections = page ? EstablishedTo(port) : 0;
                    long answers0 = plc.FaultCounters.Frames;
                    ProcessSample s0 = ProcessSample.Read(gateway.Id) ?? throw new InvalidOperationException("The gateway exited:\n" + gateway.Output);
                    var clock = Stopwatch.StartNew();
                    await Task.Delay(TimeSpan.FromSeconds(seconds));
                    ProcessSample s1 = ProcessSample.Read(gateway.Id) ?? throw new InvalidOperationException("The gateway exited:\n" + gateway.Output);
                    double cpu = (s1.CpuTicks - s0.CpuTicks) * 100.0 / ProcessSample.ClockTicksPerSecond / clock.Elapsed.TotalSeconds;
                    long answers = plc.FaultCounters.Frames - answers0;
                    (results.TryGetValue(state, out List<double>? list) ? list : results[state] = []).Add(cpu);
                    Console.WriteLine($"| {round} | {state} | {cpu:0.0} | {answers} | {cpu * 10 * clock.Elapsed.TotalSeconds / Math.Max(1, answers) * 1000:0.0} | {connections} |");
                }
                finally
                {
                    foreach (Process chromium in chromiums)
                    {
                        chromium.Kill(entireProcessTree: true);
                        await chromium.WaitForExitAsync();
                        chromium.Dispose();
                    }

                    await gateway.StopAsync();
                }
            }
        }

        await animate.CancelAsync();
        await changing.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        double off = Median(results[states[0]]);
        Console.WriteLine();
        Console.WriteLine("| State | Median CPU % | Added by the page (points of one core) |");
        Console.WriteLine("|---|---|---|");
        foreach (string state in states)
        {
            double median = Median(results[state]);
            Console.WriteLine($"| {state} | {median:0.0} | {(state == states[0] ? "—" : $"{median - off:+0.0;-0.0}")} |");
        }

        return 0;
    }

    /// <summary>Every tag's word changes once a second, so that every update a page is sent carries new values.</summary>
    private static async Task ChangeAsync(VirtualPlc plc, int tags, CancellationToken cancellationToken)
    {
        using var timer = new PeriodicTimer(TimeSpan.FromSeconds(1));
        var words = new ushort[tags];
        while (await timer.WaitForNextTickAsync(cancellationToken))
        {
            for (int i = 0; i < tags; i++)
            {
                words[i]++;
            }

            plc.WriteWords("D0", words);
        }
    }

    private static JsonObject Settings(int plcPort, int tags, int links, TimeSpan interval, int? statusPort)
    {
        var linksNode = new JsonObject();
        for (int l = 0; l < links; l++)
        {
            var groups = new JsonObject();
            for (int t = l; t < tags; t += links)
            {
                groups[$"t{t:D4}"] = new JsonObject { ["Address"] = $"D{t}", ["Type"] = "uint16", ["Interval"] = interval.ToString("c", CultureInfo.InvariantCulture), ["Log"] = "OnChange" };
            }

            linksNode[$"link{l}"] = new JsonObject
            {
                ["Tcp"] = $"127.0.0.1:{plcPort}",
                ["Serial"] = new JsonObject { ["BaudRate"] = 115200 },
                ["Groups"] = groups,
            };
        }

        var settings = new JsonObject
        {
            ["Logging"] = new JsonObject { ["LogLevel"] = new JsonObject { ["Default"] = "Warning", ["OmronHostLink.Gateway.Status"] = "Information" } },
            ["HostLink"] = new JsonObject { ["Links"] = linksNode },
        };
        if (statusPort is { } port)
        {
            settings["Status"] = new JsonObject { ["Port"] = port };
        }

        return settings;
    }

    private static Process StartBrowser(string url)
    {
        string profile = Directory.CreateTempSubdirectory("ohl-status-cpu-").FullName;
        var start = new ProcessStartInfo(Chromium)
        {
            ArgumentList =
            {
                "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--no-first-run", "--disable-dev-shm-usage", $"--user-data-dir={profile}", "--window-size=1280,900", url,
            },
            RedirectStandardError = true,
            RedirectStandardOutput = true,
        };
        Process process = Process.Start(start) ?? throw new InvalidOperationException("chromium did not start");
        process.ErrorDataReceived += (_, _) => { };
        process.OutputDataReceived += (_, _) => { };
        process.BeginErrorReadLine();
        process.BeginOutputReadLine();
        return process;
    }

    private static async Task WaitForPortAsync(int port, WorkerProcess gateway)
    {
        var clock = Stopwatch.StartNew();
        while (!Listening(port))
        {
            if (gateway.HasExited || clock.Elapsed > TimeSpan.FromMinutes(2))
            {
                throw new InvalidOperationException("The status page did not listen:\n" + gateway.Output);
            }

            await Task.Delay(100);
        }
    }

    /// <summary>Whether a socket listens on 127.0.0.1:<paramref name="port"/> (from /proc/net/tcp).</summary>
    private static bool Listening(int port) => Sockets(port).Any(s => s.State == "0A");

    /// <summary>Established connections whose local end is 127.0.0.1:<paramref name="port"/>: the pages' connections.</summary>
    private static int EstablishedTo(int port) => Sockets(port).Count(s => s.State == "01");

    private static IEnumerable<(string Local, string State)> Sockets(int port)
    {
        string local = "0100007F:" + port.ToString("X4", CultureInfo.InvariantCulture);
        return File.ReadLines("/proc/net/tcp").Skip(1)
            .Select(l => l.Split(' ', StringSplitOptions.RemoveEmptyEntries))
            .Where(f => f.Length > 3 && f[1] == local)
            .Select(f => (f[1], f[3]));
    }

    private static int FreePort()
    {
        using var listener = new System.Net.Sockets.TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        return ((IPEndPoint)listener.LocalEndpoint).Port;
    }

    private static double Median(List<double> values)
    {
        double[] sorted = values.Order().ToArray();
        return sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[(sorted.Length / 2) - 1] + sorted[sorted.Length / 2]) / 2;
    }

    private static int Option(string[] args, string name, int fallback)
        => Text(args, name) is { } text ? int.Parse(text, CultureInfo.InvariantCulture) : fallback;

    private static string? Text(string[] args, string name)
    {
        int at = Array.IndexOf(args, name);
        return at >= 0 && at + 1 < args.Length ? args[at + 1] : null;
    }
}
