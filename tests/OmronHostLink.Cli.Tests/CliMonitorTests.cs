using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;
using System.Text.Json;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Cli.Tests;

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
            ["monitor", "D0", "--interval", "30ms", "--timeout", Allowances.LosslessLineText, "--json", "--tcp", $"127.0.0.1:{port}"], output, TextWriter.Synchronized(stderr), cts.Token);
        string Out() { lock (output) { return stdout.ToString(); } }

        await Until(() => Out().Contains("\"values\":[7]", StringComparison.Ordinal), Out);
        await first.StopAsync();
        await Until(() => Out().Contains("\"status\":\"lost\"", StringComparison.Ordinal) || run.IsCompleted, Out);
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
        await using HostlinkProcess process = HostlinkProcess.Start("monitor", "D0", "--interval", "50ms", "--tcp", sim.Endpoint);
        await process.ExpectOutputAsync("D0", TimeSpan.FromSeconds(20));

        // A user who presses Ctrl+C more than once: the later ones arrive while the first is stopping the watch.
        for (int i = 0; i < 5 && !process.HasExited; i++)
        {
            process.Signal(ProgramProcess.SigInt);
            await Task.Yield();
        }

        await process.WaitForExitAsync(TimeSpan.FromSeconds(15));

        string err = process.Err;
        process.ExitCode.Should().Be(0, err);
        err.Should().NotContain(" at ");
    }

    [Fact]
    public async Task Sigterm_exits_0()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        await using HostlinkProcess process = HostlinkProcess.Start("monitor", "D0", "--interval", "50ms", "--tcp", sim.Endpoint);
        await process.ExpectOutputAsync("D0", TimeSpan.FromSeconds(20));

        process.Signal(ProgramProcess.SigTerm);
        await process.WaitForExitAsync(TimeSpan.FromSeconds(15));

        process.ExitCode.Should().Be(0, process.Err);
    }

    [Fact]
    public async Task A_poll_longer_than_the_interval_is_a_status_line_in_json_with_verbose_but_not_the_poll_that_connected()
    {
        // Every answer takes 60 ms: every poll overruns a 20 ms interval; the first also opened the connection.
        await using var sim = await SimulatedPlc.StartAsync(turnaround: TimeSpan.FromMilliseconds(60));

        CliResult r = await sim.RunAsync("monitor", "D0", "--interval", "20ms", "--count", "3", "--json", "--verbose");
        CliResult quiet = await sim.RunAsync("monitor", "D0", "--interval", "20ms", "--count", "3", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement[] lines = r.Lines().Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();
        JsonElement[] overruns = lines.Where(l => l.TryGetProperty("status", out JsonElement s) && s.GetString() == "overrun").ToArray();
        overruns.Should().ContainSingle("poll 2 overran (poll 1 connected, and poll 3 ends the watch before it is measured): {0}", r);
        overruns[0].GetProperty("unit").GetInt32().Should().Be(0);
        overruns[0].GetProperty("kind").ValueKind.Should().Be(JsonValueKind.Null);
        overruns[0].GetProperty("message").GetString().Should().Contain("longer than the 20 ms interval");
        overruns[0].TryGetProperty("time", out _).Should().BeTrue();
        lines.Where(l => l.TryGetProperty("values", out _)).Should().ContainSingle("the value did not change after the first poll");
        lines[0].GetProperty("values")[0].GetInt32().Should().Be(0, "the values come first, as the poll that overran ends before its overrun is known");
        quiet.ExitCode.Should().Be(0, quiet.ToString());
        quiet.Lines().Should().ContainSingle("without --verbose only values (and outages) are printed: {0}", quiet)
            .Which.Should().Contain("\"values\":[0]");
    }

    [Fact]
    public async Task A_poll_longer_than_the_interval_is_a_note_with_verbose_and_silent_without()
    {
        await using var sim = await SimulatedPlc.StartAsync(turnaround: TimeSpan.FromMilliseconds(60));

        CliResult verbose = await sim.RunAsync("monitor", "D0", "--interval", "20ms", "--count", "3", "--verbose");
        CliResult quiet = await sim.RunAsync("monitor", "D0", "--interval", "20ms", "--count", "3");

        verbose.ExitCode.Should().Be(0, verbose.ToString());
        verbose.Err.Split('\n').Where(l => l.Contains("overrun", StringComparison.Ordinal)).Should().ContainSingle()
            .Which.Should().MatchRegex(@"^\d\d:\d\d:\d\d\.\d{3}  unit 00 overrun: the poll took [\d.]+ ms, longer than the 20 ms interval; the next starts at once\.");
        verbose.Lines().Should().ContainSingle().Which.Should().Contain("D0");
        quiet.ExitCode.Should().Be(0, quiet.ToString());
        quiet.Err.Should().BeEmpty("a note a poll would drown the values when the interval is shorter than the line allows");
    }

    [Fact]
    public async Task An_end_code_is_an_error_that_ends_the_watch_not_an_outage()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        byte[] refusal = Encoding.ASCII.GetBytes(GoldenVectors.Get("c_rd_err_15").Frames[0]);
        Task plc = Task.Run(async () =>
        {
            // A PLC that answers every RD with end code 15 (entry number data error).
            using TcpClient client = await listener.AcceptTcpClientAsync();
            NetworkStream stream = client.GetStream();
            var buffer = new byte[256];
            while (await stream.ReadAsync(buffer) is > 0 and int n)
            {
                if (Array.IndexOf(buffer, (byte)'\r', 0, n) >= 0)
                {
                    await stream.WriteAsync(refusal);
                }
            }
        });

        using var patience = new CancellationTokenSource(TimeSpan.FromSeconds(20));
        CliResult r = await Cli.RunAsync(patience.Token, "monitor", "D0", "--interval", "10ms", "--tcp", $"127.0.0.1:{((IPEndPoint)listener.LocalEndpoint).Port}", "--json");
        listener.Stop();

        r.ExitCode.Should().Be(3, r.ToString());
        JsonElement error = r.Json().GetProperty("error");
        error.GetProperty("kind").GetString().Should().Be("endCode");
        error.GetProperty("endCode").GetString().Should().Be("15");
        r.Out.Should().NotContain("\"lost\"");
    }

    [Fact]
    public async Task Bcd_shows_a_word_that_is_not_bcd_and_reports_each_change_of_its_word()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D0", new ushort[] { 0x00A1, 0x0421 });
        (Task<int> run, Func<string> output, CancellationTokenSource stop) = Watch(sim, "monitor", "D0", "2", "--as", "bcd", "--interval", "20ms");

        await Until(() => output().Contains("(BCD 0x0421)", StringComparison.Ordinal), output);
        sim.Plc.WriteWord(PlcArea.Dm, 0, 0x00A2);
        await Until(() => output().Contains("(0x00A2)", StringComparison.Ordinal), output);
        sim.Plc.WriteWord(PlcArea.Dm, 0, 0x0042);
        await Until(() => output().Contains("(BCD 0x0042)", StringComparison.Ordinal), output);
        stop.Cancel();

        (await run.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0, output());
        string[] lines = output().Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.TrimEnd()[14..]).ToArray();
        lines.Should().Equal("D0  not BCD  (0x00A1)", "D1  421  (BCD 0x0421)", "D0  not BCD  (0x00A2)", "D0  42  (BCD 0x0042)");
    }

    [Fact]
    public async Task Text_and_numbers_are_shown_with_the_words_read()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D0", new ushort[] { 0x0000, 0x3FC0, 0x4142, 0x0000 }); // 1.5f, then "AB"
        (Task<int> floats, Func<string> floatOutput, CancellationTokenSource stopFloats) = Watch(sim, "monitor", "D0", "--as", "float", "--interval", "20ms");
        (Task<int> text, Func<string> textOutput, CancellationTokenSource stopText) = Watch(sim, "monitor", "D2", "4", "--as", "string", "--interval", "20ms", "--json");

        await Until(() => floatOutput().Contains("(0x3FC00000)", StringComparison.Ordinal) && textOutput().Contains("\"AB\"", StringComparison.Ordinal), () => floatOutput() + textOutput());
        sim.Plc.WriteWords("D1", new ushort[] { 0x4020, 0x4143 }); // 2.5f, "AC"
        await Until(() => floatOutput().Contains("(0x40200000)", StringComparison.Ordinal) && textOutput().Contains("\"AC\"", StringComparison.Ordinal), () => floatOutput() + textOutput());
        stopFloats.Cancel();
        stopText.Cancel();

        (await floats.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0, floatOutput());
        (await text.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0, textOutput());
        floatOutput().Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => l.TrimEnd()[14..]).Should().Equal("D0  1.5  (0x3FC00000)", "D0  2.5  (0x40200000)");
        JsonElement[] changes = textOutput().Split('\n', StringSplitOptions.RemoveEmptyEntries).Select(l => JsonDocument.Parse(l).RootElement.Clone()).ToArray();
        changes.Select(c => c.GetProperty("values")[0].GetString()).Should().Equal("AB", "AC");
        changes.Should().OnlyContain(c => c.GetProperty("changed").EnumerateArray().Single().GetString() == "D2");
    }

    /// <summary>Runs a command in process until <c>stop</c> is cancelled; its stdout can be read while it runs.</summary>
    private static (Task<int> Run, Func<string> Output, CancellationTokenSource Stop) Watch(SimulatedPlc sim, params string[] args)
    {
        var stdout = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        var stop = new CancellationTokenSource();
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(Cli.WithAllowance([.. args, "--tcp", sim.Endpoint]), output, TextWriter.Null, stop.Token);
        return (run, () => { lock (output) { return stdout.ToString(); } }, stop);
    }

    private static Task Until(Func<bool> condition, Func<string> output) => Eventually.UntilAsync(condition, "the monitor prints it", output);
}
