using System.Diagnostics;

namespace OmronHostLink.Cli.Tests;

/// <summary>Every time option reads the library's one duration grammar: 500ms, 1s, 2m, 00:00:02; a bare number is refused.</summary>
public sealed class CliDurationTests
{
    [Fact]
    public async Task A_bare_interval_is_refused_with_a_hint_showing_the_units()
    {
        // 100 is 100 ms to one reader and 100 s to another: nothing is polled until the unit is written.
        CliResult r = await Cli.RunAsync("monitor", "D0", "--interval", "100", "--count", "3", "--tcp", "127.0.0.1:1");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--interval: '100' has no unit; write 100ms, 100s or 100m (or 00:00:00.1 for 100ms)");
    }

    [Fact]
    public async Task An_interval_in_the_TimeSpan_form_is_read_as_configuration_reads_it()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        var clock = Stopwatch.StartNew();

        // Three polls 100 ms apart: 0.2 s; 100 s if the form were misread as seconds.
        CliResult r = await sim.RunAsync("monitor", "D0", "--interval", "00:00:00.100", "--count", "3").WaitAsync(TimeSpan.FromSeconds(30));

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
    [InlineData("5000ms")]
    [InlineData("5s")]
    [InlineData("4.5s")]
    [InlineData("1m")]
    [InlineData("00:00:05.400")]
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
        r.Err.Should().Contain($"{option}: '{value}' is not a duration; write 300ms, 1.5s, 2m or 00:00:00.300");
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
