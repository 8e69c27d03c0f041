namespace OmronHostLink.Cli.Tests;

/// <summary><c>--set key=value</c>: every client setting reaches the console through the one settings type.</summary>
public sealed class CliSetTests
{
    [Fact]
    public async Task Any_declared_setting_can_be_set_and_is_used()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWord(PlcArea.Dm, 100, 1234);

        CliResult r = await sim.RunAsync("read", "D100", "--set", "UseCompoundRead=true", "--set", "UnitSendIntervals:0=5ms", "--set", "CommandSet=Fins", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("1234");
        (r.Out + r.Err).Should().Contain("@00FA", "CommandSet=Fins made the read a FINS one");
    }

    [Theory]
    [InlineData("Protocol=Fins", "--set Protocol: is now called CommandSet; rename the key.")]
    [InlineData("UnitSendIntervals:40=1s", "--set UnitSendIntervals: names unit 40: 40 is not a unit number (0-31).")]
    [InlineData("SendIntervall=1s", "--set SendIntervall: not a Host Link client setting; did you mean SendInterval?")]
    public async Task A_setting_that_cannot_be_used_is_refused_before_anything_is_sent(string set, string message)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("read", "D100", "--set", set);

        r.ExitCode.Should().NotBe(0, r.ToString());
        r.Err.Should().Contain(message);
    }
}
