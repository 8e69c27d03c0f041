using System.Diagnostics;
using System.Net;
using System.Runtime.InteropServices;
using System.Text.Json;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Tests.Cli;

/// <summary><c>monitor</c> is a watch: it outlives outages, prints every poll on request, and Ctrl+C is a clean exit.</summary>
public sealed class CliMonitorTests
{
    [Fact]
    public async Task A_dropped_connection_is_reported_once_and_the_watch_resumes_when_the_plc_returns()
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 0, 7);
        var first = new TcpSimulatorHost(plc);
        await first.StartAsync();
        int port = first.EndPoint.Port;
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        using var cts = new CancellationTokenSource();
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(
            ["monitor", "D0", "--interval", "30ms", "--timeout", "50ms", "--json", "--tcp", $"127.0.0.1:{port}"], output, TextWriter.Synchronized(stderr), cts.Token);
        string Out() { lock (output) { return stdout.ToString(); } }

        await Until(() => Out().Contains("\"values\":[7]", StringComparison.Ordinal), Out);
        await first.StopAsync();
        await Until(() => Out().Contains("\"status\":\"lost\"", StringComparison.Ordinal) || run.IsCompleted, Out);
        await Task.Delay(200);
        plc.WriteWord(PlcArea.Dm, 0, 8);
        await using var second = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, port));
        await second.StartAsync();
        await Until(() => Out().Contains("\"values\":[8]", StringComparison.Ordinal) || run.IsCompleted, Out);
        cts.Cancel();
        int exit = await run.WaitAsync(TimeSpan.FromSeconds(10));

        exit.Should().Be(0, Out() + stderr);
        JsonElement[] lines = Out().Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();
        string?[] statuses = lines.Select(l => l.TryGetProperty("status", out JsonElement s) ? s.GetString() : null).ToArray();
        statuses.Where(s => s == "lost").Should().ContainSingle("an outage is reported once, not once per poll");
        statuses.Should().Contain("resumed");
        lines[^1].GetProperty("values")[0].GetInt32().Should().Be(8);
        stderr.ToString().Should().NotContain(" at ");
    }

    [Fact]
    public async Task An_absent_unit_is_reported_once_and_polling_goes_on()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("monitor", "D0", "--unit", "5", "--interval", "10ms", "--timeout", "30ms", "--retries", "0", "--count", "4", "--verbose");

        r.Err.Split('\n').Count(l => l.Contains(">> @05", StringComparison.Ordinal)).Should().BeGreaterThanOrEqualTo(4, "every poll tries the unit: {0}", r);
        r.Err.Split('\n').Count(l => l.Contains("unit 05", StringComparison.OrdinalIgnoreCase) && l.Contains("lost", StringComparison.OrdinalIgnoreCase))
            .Should().Be(1, "the outage is reported once: {0}", r);
        r.ExitCode.Should().Be(4, "no poll ever succeeded: {0}", r);
    }

    [Fact]
    public async Task All_prints_every_poll()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D0", new ushort[] { 7, 8 });

        CliResult r = await sim.RunAsync("monitor", "D0", "2", "--interval", "10ms", "--count", "3", "--all", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        string[] lines = r.Lines();
        lines.Should().HaveCount(3);
        JsonDocument.Parse(lines[2]).RootElement.GetProperty("changed").GetArrayLength().Should().Be(0);
        JsonDocument.Parse(lines[2]).RootElement.GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(7, 8);
    }

    [Fact]
    public async Task All_prints_every_poll_for_people_too()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("monitor", "D0", "--interval", "10ms", "--count", "3", "--all");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Lines().Where(l => l.Contains("D0", StringComparison.Ordinal)).Should().HaveCount(3);
    }

    [Fact]
    public async Task Cancellation_at_any_moment_exits_0_without_a_message()
    {
        await using var sim = await SimulatedPlc.StartAsync(turnaround: TimeSpan.FromMilliseconds(20));
        foreach (int ms in new[] { 0, 1, 5, 15, 25, 40, 70, 120 })
        {
            using var cts = new CancellationTokenSource(TimeSpan.FromMilliseconds(ms));
            CliResult r = await Cli.RunAsync(cts.Token, "monitor", "D0", "--interval", "10ms", "--tcp", sim.Endpoint);

            r.ExitCode.Should().Be(0, "cancelled after {0} ms: {1}", ms, r);
            r.Err.Should().BeEmpty("cancelled after {0} ms", ms);
        }
    }

    [Fact]
    public async Task Ctrl_c_pressed_twice_still_exits_0()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        using Process process = RealCli.Start("monitor", "D0", "--interval", "50ms", "--tcp", sim.Endpoint);
        await RealCli.WaitForOutputAsync(process, "D0");

        // A user who presses Ctrl+C more than once: the later ones arrive while the first is stopping the watch.
        for (int i = 0; i < 5 && !process.HasExited; i++)
        {
            RealCli.Signal(process, RealCli.SigInt);
            await Task.Delay(2);
        }

        await process.WaitForExitAsync().WaitAsync(TimeSpan.FromSeconds(15));

        string err = await process.StandardError.ReadToEndAsync();
        process.ExitCode.Should().Be(0, err);
        err.Should().NotContain(" at ");
    }

    [Fact]
    public async Task Sigterm_exits_0()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        using Process process = RealCli.Start("monitor", "D0", "--interval", "50ms", "--tcp", sim.Endpoint);
        await RealCli.WaitForOutputAsync(process, "D0");

        RealCli.Signal(process, RealCli.SigTerm);
        await process.WaitForExitAsync().WaitAsync(TimeSpan.FromSeconds(15));

        process.ExitCode.Should().Be(0, await process.StandardError.ReadToEndAsync());
    }

    private static async Task Until(Func<bool> condition, Func<string> output)
    {
        var clock = Stopwatch.StartNew();
        while (!condition())
        {
            if (clock.Elapsed > TimeSpan.FromSeconds(15))
            {
                throw new TimeoutException("Condition not met; output: " + output());
            }

            await Task.Delay(20);
        }
    }
}

/// <summary>The built <c>hostlink</c> program as its own process, for what only a real process has: signals.</summary>
internal static class RealCli
{
    public const int SigInt = 2;
    public const int SigTerm = 15;

    public static Process Start(params string[] args)
    {
        AllowSigIntInChildren();
        var start = new ProcessStartInfo("dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "hostlink.dll"));
        foreach (string arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        return Process.Start(start)!;
    }

    /// <summary>Reads stdout until a line contains <paramref name="text"/>.</summary>
    public static async Task WaitForOutputAsync(Process process, string text)
    {
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(20));
        while (await process.StandardOutput.ReadLineAsync(timeout.Token) is { } line)
        {
            if (line.Contains(text, StringComparison.Ordinal))
            {
                return;
            }
        }

        throw new InvalidOperationException("The program ended before printing " + text + ": " + await process.StandardError.ReadToEndAsync());
    }

    public static void Signal(Process process, int signal)
    {
        const int NoSuchProcess = 3;
        if (Kill(process.Id, signal) != 0 && Marshal.GetLastPInvokeError() != NoSuchProcess)
        {
            throw new InvalidOperationException($"kill({process.Id}, {signal}) failed: errno {Marshal.GetLastPInvokeError()}");
        }
    }

    /// <summary>
    /// A test host started in the background inherits SIGINT ignored, and so would every program it starts (an ignored
    /// signal stays ignored across exec). Ctrl+C is what is tested here, so children get the default disposition back.
    /// </summary>
    private static void AllowSigIntInChildren()
    {
        string status = File.ReadAllText("/proc/self/status");
        string line = status.Split('\n').First(l => l.StartsWith("SigIgn:", StringComparison.Ordinal));
        ulong ignored = Convert.ToUInt64(line["SigIgn:".Length..].Trim(), 16);
        if ((ignored & (1UL << (SigInt - 1))) != 0)
        {
            SetSignal(SigInt, IntPtr.Zero);
        }
    }

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    private static extern int Kill(int pid, int signal);

    [DllImport("libc", EntryPoint = "signal")]
    private static extern IntPtr SetSignal(int signal, IntPtr handler);
}
