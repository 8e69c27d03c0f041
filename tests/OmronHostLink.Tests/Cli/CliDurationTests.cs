using System.Diagnostics;

namespace OmronHostLink.Tests.Cli;

/// <summary>One duration rule for every time option: 500ms, 1s, 2m; a bare number is milliseconds.</summary>
public sealed class CliDurationTests
{
    [Fact]
    public async Task A_bare_interval_is_milliseconds()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        var clock = Stopwatch.StartNew();

        // Three polls 100 apart: 0.2 s when 100 means milliseconds, 200 s when it means seconds.
        CliResult r = await sim.RunAsync("monitor", "D0", "--interval", "100", "--count", "3").WaitAsync(TimeSpan.FromSeconds(30));

        r.ExitCode.Should().Be(0, r.ToString());
        clock.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(30));
    }

    [Fact]
    public async Task Interval_zero_polls_back_to_back()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("monitor", "D0", "--interval", "0", "--count", "5", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Lines().Should().ContainSingle("the value did not change after the first poll");
    }

    [Theory]
    [InlineData("500ms")]
    [InlineData("1s")]
    [InlineData("0.5s")]
    [InlineData("1m")]
    [InlineData("400")]
    public async Task Timeout_takes_a_duration(string timeout)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("status", "--timeout", timeout);

        r.ExitCode.Should().Be(0, r.ToString());
    }

    [Theory]
    [InlineData("status", "--timeout", "5x")]
    [InlineData("monitor", "--interval", "soon")]
    [InlineData("simulate", "--turnaround", "5x")]
    [InlineData("simulate", "--fault-late-by", "late")]
    public async Task A_bad_duration_names_the_option(string command, string option, string value)
    {
        string[] args = command == "monitor" ? [command, "D0", option, value, "--tcp", "127.0.0.1:1"]
            : command == "status" ? [command, option, value, "--tcp", "127.0.0.1:1"]
            : [command, option, value, "--tcp", "127.0.0.1:0"];

        CliResult r = await Cli.RunAsync(args);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain($"{option}: '{value}' is not a duration; use 500ms, 1s or 2m");
        r.Err.Should().NotContain("System.", "the message is in the user's words, not a .NET type name");
    }

    [Fact]
    public async Task Simulator_time_options_take_durations()
    {
        var stdout = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        using var cts = new CancellationTokenSource();
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(
            ["simulate", "--tcp", "127.0.0.1:0", "--turnaround", "20ms", "--fault-late-by", "2s"], output, TextWriter.Null, cts.Token);
        string endpoint = await CliSimulatorCommandTests.WaitForEndpointAsync(() => { lock (output) { return stdout.ToString(); } });

        CliResult status = await Cli.RunAsync("status", "--tcp", endpoint);
        cts.Cancel();

        (await run.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0, stdout.ToString());
        status.ExitCode.Should().Be(0, status.ToString());
    }
}
