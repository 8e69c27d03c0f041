using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>model</c> describes a model; <c>--model</c> checks reads against it; <c>simulate --model</c> emulates one.</summary>
public sealed class CliModelTests
{
    [Fact]
    public async Task Model_with_a_name_prints_the_family_its_ranges_and_what_it_supports()
    {
        CliResult r = await Cli.RunAsync("model", "CPM1A");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("CPM1/CPM1A (CPM1A)").And.Contain("MM model code: 11")
            .And.Contain("D0–D1023").And.Contain("D6144–D6655").And.Contain("D1024–D6143")
            .And.Contain("FINS over Host Link: no").And.Contain("compound read (QQ): yes");

        JsonElement j = (await Cli.RunAsync("model", "cp1e-e", "--json")).Json();
        j.GetProperty("family").GetString().Should().Be("CP1E E-type");
        j.GetProperty("mmCode").ValueKind.Should().Be(JsonValueKind.Null);
        j.GetProperty("areas").EnumerateArray().Should().Contain(a => a.GetProperty("range").GetString() == "D0–D2047");
    }

    [Fact]
    public async Task Model_list_names_every_profile()
    {
        CliResult r = await Cli.RunAsync("model", "--list");

        r.ExitCode.Should().Be(0, r.ToString());
        foreach (PlcModelProfile profile in PlcModelProfile.All)
        {
            r.Out.Should().Contain(profile.Name);
        }
    }

    [Fact]
    public async Task An_unknown_model_name_is_a_usage_error()
    {
        CliResult r = await Cli.RunAsync("model", "CPM9");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("'CPM9' is not a known PLC model");
    }

    [Fact]
    public async Task Read_with_a_model_refuses_what_it_lacks_and_names_it()
    {
        await using var sim = await InProcessSimulator.StartAsync("--model", "CP1E-E");

        CliResult beyond = await Cli.RunAsync("read", "D2048", "--model", "CP1E-E", "--tcp", sim.Endpoint);
        CliResult last = await Cli.RunAsync("read", "D2047", "--model", "CP1E-E", "--json", "--tcp", sim.Endpoint);
        CliResult unknown = await Cli.RunAsync("read", "D0", "--model", "CPM9", "--tcp", sim.Endpoint);

        beyond.ExitCode.Should().Be(2, beyond.ToString());
        beyond.Err.Should().Contain("D2048 is beyond the DM area of a CP1E E-type (D0–D2047)");
        last.ExitCode.Should().Be(0, last.ToString());
        unknown.ExitCode.Should().Be(2, unknown.ToString());
        unknown.Err.Should().Contain("--model: 'CPM9' is not a known PLC model");
    }

    [Fact]
    public async Task Model_against_a_simulator_emulating_a_C200HS_names_what_code_12_covers()
    {
        await using var sim = await InProcessSimulator.StartAsync("--model", "C200HS");

        CliResult r = await Cli.RunAsync("model", "--tcp", sim.Endpoint);
        CliResult auto = await Cli.RunAsync("read", "D6656", "--model", "auto", "--tcp", sim.Endpoint);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("code 12").And.Contain("PLC answering MM 12 (C200H, C200HS, C200HX/HG/HE");
        auto.ExitCode.Should().Be(2, auto.ToString());
        auto.Err.Should().Contain("D6656 is beyond the DM area of a PLC answering MM 12");
    }
}
