using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>Bits: no silent protocol switch, and several bits are one command.</summary>
public sealed class CliBitTests
{
    [Fact]
    public async Task A_bit_write_with_c_mode_is_refused_naming_both_ways_and_nothing_is_sent()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "CIO100.07", "on");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--fins").And.Contain("--read-modify-write");
        sim.Host.AcceptedConnections.Should().Be(0, "nothing is sent");
        sim.Plc.GetBit("CIO100.07").Should().BeFalse();
    }

    [Theory]
    [InlineData("read", "W30")]
    [InlineData("write", "W30", "1")]
    [InlineData("write", "W30.01", "1", "--read-modify-write")]
    public async Task The_work_area_without_fins_says_add_fins(params string[] args)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync(args);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("add --fins");
    }

    [Fact]
    public async Task Several_bits_with_fins_are_one_command()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "CIO100.14", "1", "1", "1", "--fins", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        Sent(r, "FA").Should().Be(1, "three bits in one range are one FINS 0102: {0}", r.Err);
        sim.Plc.GetBit("CIO100.14").Should().BeTrue();
        sim.Plc.GetBit("CIO100.15").Should().BeTrue();
        sim.Plc.GetBit("CIO101.00").Should().BeTrue();
    }

    [Fact]
    public async Task Several_bits_with_read_modify_write_are_one_read_and_one_write()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D7", new ushort[] { 0x0101, 0x8000 });

        CliResult r = await sim.RunAsync("write", "D7.14", "1", "0", "1", "--read-modify-write", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        Sent(r, "RD").Should().Be(1, r.Err);
        Sent(r, "WD").Should().Be(1, r.Err);
        sim.Plc.ReadWords("D7", 2).Should().Equal(new ushort[] { 0x4101, 0x8001 }, "D7.14 on, D7.15 off, D8.00 on; the other bits kept");
    }

    [Theory]
    [InlineData(false, "RG")]
    [InlineData(true, "FA")]
    public async Task Timer_flags_are_one_command(bool fins, string header)
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetFlag(PlcArea.Timer, 1, true);
        sim.Plc.SetFlag(PlcArea.Timer, 3, true);
        string[] args = ["read", "T0", "4", "--as", "bit", "--json", "--verbose"];

        CliResult r = await sim.RunAsync(fins ? [.. args, "--fins"] : args);

        r.ExitCode.Should().Be(0, r.ToString());
        Sent(r, header).Should().Be(1, r.Err);
        r.Json().GetProperty("values").EnumerateArray().Select(v => v.GetBoolean()).Should().Equal(false, true, false, true);
    }

    [Fact]
    public async Task Counter_flags_are_one_command_in_monitor_too()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetFlag(PlcArea.Counter, 12, true);

        CliResult r = await sim.RunAsync("monitor", "C10", "3", "--as", "bit", "--count", "1", "--json", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        Sent(r, "RG").Should().Be(1, r.Err);
        JsonDocument.Parse(r.Lines()[0]).RootElement.GetProperty("values").EnumerateArray().Select(v => v.GetBoolean()).Should().Equal(false, false, true);
    }

    /// <summary>How many command frames with <paramref name="header"/> went to unit 00 (from the --verbose trace).</summary>
    private static int Sent(CliResult r, string header)
        => r.Err.Split('\n').Count(l => l.Contains(">> @00" + header, StringComparison.Ordinal));
}
