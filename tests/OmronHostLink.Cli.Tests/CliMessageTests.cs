using System.Globalization;
using System.Text.RegularExpressions;

namespace OmronHostLink.Cli.Tests;

/// <summary>Messages in the user's words: the command that went unanswered, the option that is wrong, help that helps.</summary>
public sealed class CliMessageTests
{
    [Fact]
    public async Task A_timeout_names_the_command_and_the_real_time_waited()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("read", "D0", "--unit", "5", "--timeout", "40ms", "--retries", "2");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain("unit 05").And.Contain("RD").And.Contain("3 attempts");
        r.Err.Should().NotContain("TS", "the resynchronisation fence is the link's business, not the user's");
        Match waited = Regex.Match(r.Err, @"(\d+) ms");
        waited.Success.Should().BeTrue(r.Err);
        int.Parse(waited.Groups[1].Value, CultureInfo.InvariantCulture).Should().BeGreaterThanOrEqualTo(3 * 40, "three attempts of at least 40 ms each were waited for: {0}", r.Err);
    }

    [Theory]
    [InlineData("--baud", "12345", "--baud: 12345 is not")]
    [InlineData("--baud", "fast", "--baud: 'fast' is not")]
    [InlineData("--unit", "x", "--unit: 'x' is not")]
    [InlineData("--retries", "many", "--retries: 'many' is not")]
    [InlineData("--data-bits", "6", "--data-bits: 6 is not")]
    [InlineData("--parity", "mark", "--parity: 'mark' is not")]
    public async Task A_bad_option_value_is_named_in_the_users_words(string option, string value, string expected)
    {
        CliResult r = await Cli.RunAsync("status", option, value, "--tcp", "127.0.0.1:1");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain(expected);
        r.Err.Should().NotContain("System.").And.NotContain("(Parameter").And.NotContain("SerialLineSettings");
    }

    [Fact]
    public async Task A_bad_as_names_the_option_and_the_choices()
    {
        CliResult r = await Cli.RunAsync("read", "D1", "--as", "quad", "--tcp", "127.0.0.1:1");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--as: 'quad' is not one of word, bcd, int16");
    }

    [Fact]
    public async Task Help_as_a_command_prints_the_usage()
    {
        CliResult root = await Cli.RunAsync("help");
        CliResult read = await Cli.RunAsync("help", "read");

        root.ExitCode.Should().Be(0, root.ToString());
        root.Out.Should().Contain("Usage:").And.Contain("scan").And.Contain("monitor");
        read.ExitCode.Should().Be(0, read.ToString());
        read.Out.Should().Contain("read <address> [<count>]").And.Contain("--as");
    }

    [Fact]
    public async Task Help_for_an_unknown_command_exits_2()
    {
        CliResult r = await Cli.RunAsync("help", "nosuchcommand");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("nosuchcommand");
    }

    [Theory]
    [InlineData("read", "count")]
    [InlineData("monitor", "count")]
    [InlineData("test", "text")]
    public async Task Optional_arguments_are_shown_as_optional(string command, string argument)
    {
        CliResult r = await Cli.RunAsync(command, "--help");

        string arguments = r.Out[r.Out.IndexOf("Arguments:", StringComparison.Ordinal)..r.Out.IndexOf("Options:", StringComparison.Ordinal)];
        arguments.Should().MatchRegex($@"\[<?{argument}>?\]", "the Arguments section marks {0} optional: {1}", argument, arguments);
    }

    [Fact]
    public async Task Choices_are_case_insensitive()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);
        sim.Plc.WriteWords("D10", new ushort[] { 0x0000, 0x3FC0 });

        CliResult mode = await sim.RunAsync("mode", "PROGRAM", "--yes");
        CliResult read = await sim.RunAsync("read", "D10", "--as", "FLOAT", "--json");
        CliResult parity = await sim.RunAsync("status", "--parity", "EVEN");

        mode.ExitCode.Should().Be(0, mode.ToString());
        sim.Plc.Mode.Should().Be(PlcMode.Program);
        read.ExitCode.Should().Be(0, read.ToString());
        read.Json().GetProperty("values")[0].GetDouble().Should().Be(1.5);
        parity.ExitCode.Should().Be(0, parity.ToString());
    }

    [Fact]
    public async Task Errors_exit_5_when_error_bits_are_set()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetError(0x8000, 0x0001);

        CliResult set = await sim.RunAsync("errors");
        CliResult json = await sim.RunAsync("errors", "--json");

        set.ExitCode.Should().Be(5, set.ToString());
        json.ExitCode.Should().Be(5, json.ToString());
        json.Json().GetProperty("hasErrors").GetBoolean().Should().BeTrue();
    }

    [Fact]
    public async Task Errors_exit_0_when_no_error_bit_is_set()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("errors");

        r.ExitCode.Should().Be(0, r.ToString());
    }
}
