namespace OmronHostLink.Cli.Tests;

/// <summary>String writes leave no old text behind, and say what they wrote.</summary>
public sealed class CliStringTests
{
    [Fact]
    public async Task A_shorter_string_leaves_no_old_text_behind()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        (await sim.RunAsync("write", "D50", "Hello world", "--as", "string")).ExitCode.Should().Be(0);

        CliResult write = await sim.RunAsync("write", "D50", "AB", "--as", "string");
        CliResult read = await sim.RunAsync("read", "D50", "16", "--as", "string", "--json");

        write.ExitCode.Should().Be(0, write.ToString());
        read.Json().GetProperty("values")[0].GetString().Should().Be("AB");
        sim.Plc.ReadWords("D50", 3).Should().Equal(new ushort[] { 0x4142, 0x0000, 0x6F20 }, "the text ends with a NUL word, as Omron strings do; nothing past it is touched");
    }

    [Fact]
    public async Task An_odd_length_string_ends_in_its_last_word()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D50", new ushort[] { 0x4141, 0x4141, 0x4141 });

        CliResult r = await sim.RunAsync("write", "D50", "XYZ", "--as", "string");

        r.ExitCode.Should().Be(0, r.ToString());
        sim.Plc.ReadWords("D50", 3).Should().Equal(new ushort[] { 0x5859, 0x5A00, 0x4141 });
    }

    [Fact]
    public async Task A_field_length_pads_the_whole_field_with_nul()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D50", PlcWords.FromString("OLD TEXT HERE"));

        CliResult r = await sim.RunAsync("write", "D50", "AB", "--as", "string", "--length", "8");

        r.ExitCode.Should().Be(0, r.ToString());
        sim.Plc.ReadWords("D50", 5).Should().Equal(new ushort[] { 0x4142, 0, 0, 0, PlcWords.FromString("OLD TEXT HERE")[4] }, "8 characters are 4 words; D54 is not part of the field");
    }

    [Fact]
    public async Task Space_padding_fills_the_field_with_spaces()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D50", PlcWords.FromString("OLD TEXT"));

        CliResult r = await sim.RunAsync("write", "D50", "AB", "--as", "string", "--length", "8", "--pad", "space");

        r.ExitCode.Should().Be(0, r.ToString());
        sim.Plc.ReadWords("D50", 4).Should().Equal(PlcWords.FromString("AB      "));
    }

    [Fact]
    public async Task Text_longer_than_the_field_is_refused()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "D50", "TOO LONG", "--as", "string", "--length", "4");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--length");
        sim.Host.AcceptedConnections.Should().Be(0);
    }

    [Fact]
    public async Task The_summary_shows_the_text_written()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "D50", "PUMP", "7", "--as", "string");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("\"PUMP 7\"").And.Contain("D50");
    }
}
