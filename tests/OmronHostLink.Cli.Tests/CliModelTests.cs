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

    [Fact]
    public async Task Write_with_a_model_refuses_what_it_lacks_or_may_not_write_and_names_it()
    {
        await using var sim = await InProcessSimulator.StartAsync("--model", "CPM1A");

        CliResult beyond = await Cli.RunAsync("write", "D1024", "1", "--model", "CPM1A", "--tcp", sim.Endpoint);
        CliResult readOnly = await Cli.RunAsync("write", "CIO253", "1", "--model", "CPM1A", "--tcp", sim.Endpoint);
        CliResult fine = await Cli.RunAsync("write", "D1023", "7", "--model", "CPM1A", "--tcp", sim.Endpoint);

        beyond.ExitCode.Should().Be(2, beyond.ToString());
        beyond.Err.Should().Contain("D1024 is beyond the DM area of a CPM1/CPM1A (D0–D1023, D6144–D6655)");
        readOnly.ExitCode.Should().Be(2, readOnly.ToString());
        readOnly.Err.Should().Contain("CIO253 is read-only on a CPM1/CPM1A");
        fine.ExitCode.Should().Be(0, fine.ToString());
        (await Cli.RunAsync("read", "D1023", "--model", "CPM1A", "--json", "--tcp", sim.Endpoint)).Out.Should().Contain("\"values\":[7]");
    }

    [Fact]
    public async Task Fins_to_a_model_without_it_is_a_usage_error_that_says_to_leave_out_fins()
    {
        await using var sim = await InProcessSimulator.StartAsync("--model", "CPM1A");

        CliResult r = await Cli.RunAsync("read", "D0", "--fins", "--model", "CPM1A", "--tcp", sim.Endpoint);

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("does not take FINS commands over Host Link; leave out --fins").And.NotContain("NotSupportedException");
    }

    [Fact]
    public async Task The_compatible_mode_is_emulated_by_simulate_and_checked_by_read()
    {
        await using var modeC = await InProcessSimulator.StartAsync("--compatible-mode", "c");

        CliResult asC = await Cli.RunAsync("read", "D0", "60", "--compatible-mode", "c", "--json", "--tcp", modeC.Endpoint);
        CliResult unset = await Cli.RunAsync("read", "D0", "60", "--json", "--tcp", modeC.Endpoint);
        CliResult asA = await Cli.RunAsync("read", "D0", "60", "--compatible-mode", "a", "--retries", "0", "--tcp", modeC.Endpoint);
        CliResult modeD = await Cli.RunAsync("simulate", "--compatible-mode", "d", "--tcp", "127.0.0.1:0");

        asC.ExitCode.Should().Be(0, asC.ToString());
        unset.ExitCode.Should().Be(0, unset.ToString());
        asA.ExitCode.Should().Be(4, asA.ToString());
        asA.Err.Should().Contain("first frame carried 29 words; a Serial Communications Unit in Host Link-compatible mode A (CS/CJ/C) sends 30");
        modeD.ExitCode.Should().Be(2, modeD.ToString());
        modeD.Err.Should().Contain("--compatible-mode");
    }
}
