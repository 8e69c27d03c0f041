using System.Globalization;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>--as double</c>: an LREAL in four words, lowest word first, read and written through the console.</summary>
public sealed class CliDoubleTests
{
    private const double Value = -1234.5678;

    /// <summary>The LREAL's four words, lowest first, from the IEEE 754 bits (not from the library's codec).</summary>
    private static ushort[] Words(double value)
    {
        long bits = BitConverter.DoubleToInt64Bits(value);
        return [(ushort)bits, (ushort)(bits >> 16), (ushort)(bits >> 32), (ushort)(bits >> 48)];
    }

    [Fact]
    public async Task Read_as_double_decodes_an_lreal_from_four_words()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D0", Words(Value));

        CliResult json = await sim.RunAsync("read", "D0", "1", "--as", "double", "--json");
        CliResult human = await sim.RunAsync("read", "D0", "1", "--as", "double");

        json.ExitCode.Should().Be(0, json.ToString());
        json.Json().GetProperty("as").GetString().Should().Be("double");
        json.Json().GetProperty("values")[0].GetDouble().Should().Be(Value);
        human.ExitCode.Should().Be(0, human.ToString());
        human.Lines().Should().ContainSingle().Which.Should().Contain("D0").And.Contain(Value.ToString("R", CultureInfo.InvariantCulture));
    }

    [Fact]
    public async Task Read_of_two_doubles_takes_eight_words()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("D10", [.. Words(Value), .. Words(0.1)]);

        CliResult r = await sim.RunAsync("read", "D10", "2", "--as", "double", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("values").EnumerateArray().Select(v => v.GetDouble()).Should().Equal(Value, 0.1);
    }

    [Fact]
    public async Task Write_as_double_stores_the_four_words()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("write", "D20", "-1234.5678", "--as", "double", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        sim.Plc.ReadWords("D20", 4).Should().Equal(Words(Value));
    }
}
