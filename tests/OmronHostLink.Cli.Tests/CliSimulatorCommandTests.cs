using System.Text.RegularExpressions;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>demo</c>, <c>simulate</c> and <c>ports</c>.</summary>
public sealed class CliSimulatorCommandTests
{
    [Fact]
    public async Task Demo_runs_without_hardware_and_shows_the_frames()
    {
        CliResult r = await Cli.RunAsync("demo");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain(">> @00TS").And.Contain("<< @00TS");
        r.Out.Should().Contain(">> @00MS").And.Contain(">> @00MF").And.Contain(">> @00RD0100003");
        r.Out.Should().Contain("RUN").And.Contain("D129");
    }

    [Fact]
    public async Task Simulate_serves_until_cancelled_and_stops_cleanly()
    {
        var stdout = new StringWriter();
        var stderr = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        using var cts = new CancellationTokenSource();
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(["simulate", "--tcp", "127.0.0.1:0", "--units", "0,2", "--mode", "run"], output, TextWriter.Synchronized(stderr), cts.Token);

        string endpoint = await WaitForEndpointAsync(() => { lock (output) { return stdout.ToString(); } });
        CliResult status = await Cli.RunAsync("status", "--unit", "2", "--json", "--tcp", endpoint);
        CliResult write = await Cli.RunAsync("write", "D0", "1", "--tcp", endpoint);
        cts.Cancel();
        int exit = await run.WaitAsync(TimeSpan.FromSeconds(10));

        status.ExitCode.Should().Be(0, status.ToString());
        status.Json().GetProperty("mode").GetString().Should().Be("RUN");
        write.ExitCode.Should().Be(3, "the simulated PLC refuses writes in RUN mode: {0}", write);
        exit.Should().Be(0, stderr.ToString());
        stdout.ToString().Should().Contain("Simulator stopped.");
    }

    [Fact]
    public async Task Simulate_loads_initial_memory_from_json()
    {
        string file = Path.Combine(Path.GetTempPath(), $"hostlink-cli-{Guid.NewGuid():N}.json");
        await File.WriteAllTextAsync(file, "{\"D100\":[11,22],\"mode\":\"monitor\"}");
        try
        {
            var stdout = new StringWriter();
            TextWriter output = TextWriter.Synchronized(stdout);
            using var cts = new CancellationTokenSource();
            Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(["simulate", "--tcp", "127.0.0.1:0", "--memory", file], output, TextWriter.Null, cts.Token);
            string endpoint = await WaitForEndpointAsync(() => { lock (output) { return stdout.ToString(); } });

            CliResult read = await Cli.RunAsync("read", "D100", "2", "--json", "--tcp", endpoint);
            cts.Cancel();
            (await run.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0);

            read.Json().GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(11, 22);
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public async Task Simulate_with_a_bad_memory_file_exits_2()
    {
        string file = Path.Combine(Path.GetTempPath(), $"hostlink-cli-{Guid.NewGuid():N}.json");
        await File.WriteAllTextAsync(file, "{\"Q1\":5}");
        try
        {
            CliResult r = await Cli.RunAsync("simulate", "--tcp", "127.0.0.1:0", "--memory", file);

            r.ExitCode.Should().Be(2, r.ToString());
            r.Err.Should().Contain("Q1");
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public async Task Ports_lists_ports_as_json()
    {
        CliResult r = await Cli.RunAsync("ports", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("ports").ValueKind.Should().Be(System.Text.Json.JsonValueKind.Array);
    }

    internal static async Task<string> WaitForEndpointAsync(Func<string> output)
    {
        Match Endpoint() => Regex.Match(output(), @"on (127\.0\.0\.1:\d+)\.");
        await Eventually.UntilAsync(() => Endpoint().Success, "the simulator reports its end point", output);
        return Endpoint().Groups[1].Value;
    }
}
