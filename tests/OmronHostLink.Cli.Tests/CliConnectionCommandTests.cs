using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>status, errors, model, test, mode, scan, raw against the simulator: output and exit codes.</summary>
public sealed class CliConnectionCommandTests
{
    [Fact]
    public async Task Status_prints_mode_status_word_and_message()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);
        sim.Plc.FalMessage = "LOW AIR";

        CliResult r = await sim.RunAsync("status");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("RUN").And.Contain("LOW AIR").And.Contain("0x0");
        r.Err.Should().BeEmpty();
    }

    [Fact]
    public async Task Status_json_has_the_documented_fields()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Monitor);

        JsonElement j = (await sim.RunAsync("status", "--json")).Json();

        j.GetProperty("unit").GetInt32().Should().Be(0);
        j.GetProperty("mode").GetString().Should().Be("MONITOR");
        j.GetProperty("statusWord").ValueKind.Should().Be(JsonValueKind.Number);
        j.GetProperty("message").ValueKind.Should().Be(JsonValueKind.Null);
    }

    [Fact]
    public async Task Errors_lists_the_bits_that_are_on_and_clear_clears_them()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.SetError(0x8000, 0x0001);

        CliResult human = await sim.RunAsync("errors");
        human.ExitCode.Should().Be(5, "error bits are on: {0}", human);
        human.Out.Should().Contain("word 1 bit 15").And.Contain("word 2 bit 00");

        JsonElement j = (await sim.RunAsync("errors", "--clear", "--json")).Json();
        j.GetProperty("hasErrors").GetBoolean().Should().BeTrue();
        j.GetProperty("words").EnumerateArray().Select(e => e.GetInt32()).Should().Equal(0x8000, 0x0001);
        j.GetProperty("cleared").GetBoolean().Should().BeTrue();
        sim.Plc.Errors.HasErrors.Should().BeFalse();
    }

    [Fact]
    public async Task Model_names_the_family()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("model");
        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("CS/CJ");

        JsonElement j = (await sim.RunAsync("model", "--json")).Json();
        j.GetProperty("code").GetString().Should().Be("30");
        j.GetProperty("model").GetString().Should().Be("CS/CJ");
    }

    [Fact]
    public async Task Test_echoes_the_text()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("test", "ABC 123");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("echoed \"ABC 123\"");
    }

    [Fact]
    public async Task Test_text_that_would_break_the_frame_is_refused_before_connecting()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("test", "A*B");

        r.ExitCode.Should().Be(2, r.ToString());
        sim.Host.AcceptedConnections.Should().Be(0);
    }

    [Fact]
    public async Task Mode_without_yes_refuses_and_leaves_the_plc_alone()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("mode", "program");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().Contain("--yes");
        sim.Plc.Mode.Should().Be(PlcMode.Run);
        sim.Host.AcceptedConnections.Should().Be(0);
    }

    [Fact]
    public async Task Mode_with_yes_changes_the_mode()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("mode", "program", "--yes");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Should().Contain("PROGRAM");
        sim.Plc.Mode.Should().Be(PlcMode.Program);

        JsonElement j = (await sim.RunAsync("mode", "monitor", "--yes", "--json")).Json();
        j.GetProperty("mode").GetString().Should().Be("MONITOR");
        sim.Plc.Mode.Should().Be(PlcMode.Monitor);
    }

    [Fact]
    public async Task Scan_lists_the_units_that_answer()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run, units: [0, 3]);

        CliResult r = await sim.RunAsync("scan", "--units", "0-4", "--timeout", Cli.ScanTimeout, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        JsonElement[] units = r.Json().GetProperty("units").EnumerateArray().ToArray();
        units.Select(u => u.GetProperty("unit").GetInt32()).Should().Equal(0, 3);
        units.Should().OnlyContain(u => u.GetProperty("mode").GetString() == "RUN" && u.GetProperty("modelCode").GetString() == "30");
    }

    [Fact]
    public async Task Scan_with_no_answer_exits_4()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [7]);

        CliResult r = await sim.RunAsync("scan", "--units", "1,2", "--timeout", "50ms");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain("No unit answered");
    }

    [Fact]
    public async Task Raw_prints_the_answer_frame()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("raw", "MS");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Out.Trim().Should().StartWith("@00MS00").And.EndWith("*\\r");

        JsonElement j = (await sim.RunAsync("raw", "RD01000002", "--json")).Json();
        j.GetProperty("sent")[0].GetString().Should().StartWith("@00RD01000002");
        j.GetProperty("received")[0].GetString().Should().StartWith("@00RD00");
        j.GetProperty("text").GetString().Should().Be("0000000000");
    }

    [Fact]
    public async Task Raw_error_end_code_exits_3_after_printing_the_answer()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("raw", "WD01001234");

        r.ExitCode.Should().Be(3, r.ToString());
        r.Out.Should().StartWith("@00WD01");
        r.Err.Should().Contain("01").And.Contain("RUN mode");
    }

    [Fact]
    public async Task Raw_unknown_header_answered_IC_exits_3()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("raw", "ZZ");

        r.ExitCode.Should().Be(3, r.ToString());
        r.Out.Should().Contain("@00IC");
        r.Err.Should().Contain("IC");
    }

    [Theory]
    [InlineData("M*S")]
    [InlineData("@00MS")]
    [InlineData("M")]
    public async Task Raw_text_that_would_break_framing_is_refused(string text)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("raw", text);

        r.ExitCode.Should().Be(2, r.ToString());
        sim.Host.AcceptedConnections.Should().Be(0);
    }

    [Fact]
    public async Task Verbose_prints_every_frame_with_direction_on_stderr()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("model", "--json", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("code").GetString().Should().Be("30");
        r.Err.Should().MatchRegex(@"\d\d:\d\d:\d\d\.\d{3} >> @00MM").And.MatchRegex(@"\d\d:\d\d:\d\d\.\d{3} << @00MM00");
    }
}
