using OmronHostLink.Cli;

namespace OmronHostLink.Cli.Tests;

/// <summary>Every exit code: 0 success, 2 invalid input (nothing sent), 3 end code, 4 communication, 1 anything else.</summary>
public sealed class CliExitCodeTests
{
    [Theory]
    [InlineData("read", "D99999")]
    [InlineData("read", "Q100")]
    [InlineData("read", "D100", "0")]
    [InlineData("read", "D100", "many")]
    [InlineData("read", "D10000", "--as", "word")]
    [InlineData("read", "D100.05", "--as", "word")]
    [InlineData("read", "D100", "--as", "bit")]
    [InlineData("write", "D100", "70000")]
    [InlineData("write", "D100", "-1")]
    [InlineData("write", "D100", "12", "--as", "bcd", "--unit", "40")]
    [InlineData("write", "D100", "10000", "--as", "bcd")]
    [InlineData("write", "D100.01", "maybe")]
    [InlineData("write", "A10", "1")]
    [InlineData("write", "D100", "1.5x", "--as", "float")]
    [InlineData("monitor", "D100", "--interval", "soon")]
    [InlineData("status", "--unit", "32")]
    [InlineData("status", "--timeout", "0")]
    [InlineData("status", "--baud", "1234")]
    public async Task Invalid_input_exits_2_and_sends_nothing(params string[] args)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync(args);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().NotBeNullOrWhiteSpace();
        r.Out.Should().BeEmpty();
        sim.Host.AcceptedConnections.Should().Be(0, "invalid input is refused before connecting");
    }

    [Theory]
    [InlineData("read")]
    [InlineData("nosuchcommand")]
    [InlineData("status", "--baud", "fast", "--tcp", "127.0.0.1:1")]
    [InlineData("status", "--parity", "mark", "--tcp", "127.0.0.1:1")]
    [InlineData("status", "--data-bits", "6", "--tcp", "127.0.0.1:1")]
    [InlineData("read", "D1", "--as", "quad", "--tcp", "127.0.0.1:1")]
    [InlineData("mode", "stop", "--yes", "--tcp", "127.0.0.1:1")]
    [InlineData("status", "--tcp", "127.0.0.1:1", "--bogus")]
    [InlineData("simulate", "--fault-drop", "2")]
    [InlineData()]
    public async Task Parse_errors_exit_2(params string[] args)
    {
        CliResult r = await Cli.RunAsync(args);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--help");
    }

    [Fact]
    public async Task Missing_port_and_tcp_exits_2_with_a_clear_sentence()
    {
        CliResult r = await Cli.RunAsync("status");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--port").And.Contain("--tcp");
    }

    [Fact]
    public async Task Both_port_and_tcp_exits_2()
    {
        CliResult r = await Cli.RunAsync("status", "--port", "/dev/ttyS0", "--tcp", "127.0.0.1:9600");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("not both");
    }

    [Fact]
    public async Task Bad_tcp_endpoint_exits_2()
    {
        CliResult r = await Cli.RunAsync("status", "--tcp", "localhost");

        r.ExitCode.Should().Be(2, r.ToString());
    }

    [Fact]
    public async Task Unit_the_simulator_does_not_own_times_out_with_exit_4()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("read", "D0", "--unit", "5", "--timeout", "50ms", "--retries", "0");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain("ms");
        r.Err.Should().NotContain(" at ", "a stack trace is printed only with --verbose");
    }

    [Fact]
    public async Task Stack_trace_only_with_verbose()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("status", "--unit", "6", "--timeout", "30ms", "--retries", "0", "--verbose");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain("HostLinkTimeoutException").And.Contain(" at ");
        r.Err.Should().Contain(">> @06MS");
    }

    [Fact]
    public async Task Closed_tcp_port_exits_4()
    {
        CliResult r = await Cli.RunAsync("status", "--tcp", $"127.0.0.1:{Cli.ClosedPort()}");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain("Cannot connect");
    }

    [Fact]
    public async Task Serial_port_that_cannot_open_exits_4()
    {
        string missing = Path.Combine(Path.GetTempPath(), "no-such-tty-" + Guid.NewGuid().ToString("N"));

        CliResult r = await Cli.RunAsync("status", "--port", missing);

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain(missing);
    }

    [Fact]
    public async Task Cancelled_exchange_exits_1()
    {
        await using var sim = await SimulatedPlc.StartAsync(turnaround: TimeSpan.FromSeconds(3));
        using var cts = new CancellationTokenSource(TimeSpan.FromMilliseconds(300));

        CliResult r = await Cli.RunAsync(cts.Token, "status", "--timeout", "10s", "--tcp", sim.Endpoint);

        r.ExitCode.Should().Be(1, r.ToString());
        r.Err.Should().Contain("Cancelled");
    }

    [Fact]
    public void Exception_kinds_map_to_their_exit_codes()
    {
        ExitCodes.For(new UsageException("x")).Should().Be(2);
        ExitCodes.For(new ArgumentOutOfRangeException("x")).Should().Be(2);
        ExitCodes.For(new HostLinkEndCodeException(EndCode.NotExecutableInRunMode, "WD", 0)).Should().Be(3);
        ExitCodes.For(new FinsEndCodeException(new OmronHostLink.Protocol.Fins.FinsEndCode(0x2101), 0x0102, 0)).Should().Be(3);
        ExitCodes.For(new HostLinkTimeoutException("x", TimeSpan.FromSeconds(1))).Should().Be(4);
        ExitCodes.For(new HostLinkFrameException(FrameError.BadFcs, "x")).Should().Be(4);
        ExitCodes.For(new HostLinkConnectionException("x")).Should().Be(4);
        ExitCodes.For(new InvalidOperationException("x")).Should().Be(1);
    }

    [Fact]
    public async Task Help_exits_0()
    {
        CliResult r = await Cli.RunAsync("read", "--help");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("--as").And.Contain("--tcp");
    }
}
