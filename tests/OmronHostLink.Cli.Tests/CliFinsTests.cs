using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary>The same commands with <c>--fins</c>: FINS over Host Link (FA) against the simulator.</summary>
public sealed class CliFinsTests
{
    [Fact]
    public async Task Read_with_fins_reaches_areas_c_mode_cannot()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.WriteWords("W30", new ushort[] { 0x1234 });
        sim.Plc.WriteWords("D20000", new ushort[] { 7, 8 });

        CliResult cmode = await sim.RunAsync("read", "W30");
        JsonElement w = (await sim.RunAsync("read", "W30", "--fins", "--json")).Json();
        JsonElement d = (await sim.RunAsync("read", "D20000", "2", "--fins", "--json")).Json();

        cmode.ExitCode.Should().Be(2, "C-mode has no command for the work area: {0}", cmode);
        w.GetProperty("values")[0].GetInt32().Should().Be(0x1234);
        d.GetProperty("values").EnumerateArray().Select(v => v.GetInt32()).Should().Equal(7, 8);
    }

    [Fact]
    public async Task Status_with_fins_says_the_status_word_is_not_reported_rather_than_guessing_it()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        // UM is writable: the MS status word says so (bit 7); the FINS status read has no such bit.
        CliResult cmode = await sim.RunAsync("status");
        CliResult fins = await sim.RunAsync("status", "--fins");
        JsonElement j = (await sim.RunAsync("status", "--fins", "--json")).Json();

        cmode.Out.Should().Contain("User memory writable: yes");
        fins.ExitCode.Should().Be(0, fins.ToString());
        fins.Out.Should().Contain("RUN").And.Contain("User memory writable: not reported").And.NotContain("write-protected");
        j.GetProperty("mode").GetString().Should().Be("RUN");
        j.GetProperty("statusWord").ValueKind.Should().Be(JsonValueKind.Null);
        j.GetProperty("userMemoryWritable").ValueKind.Should().Be(JsonValueKind.Null);
    }

    [Fact]
    public async Task Write_bit_with_fins_writes_the_bit_directly()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult r = await sim.RunAsync("write", "CIO10.03", "1", "--fins", "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Err.Should().Contain(">> @00FA");
        sim.Plc.GetBit("CIO10.03").Should().BeTrue();
    }

    [Fact]
    public async Task Status_and_mode_with_fins()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult mode = await sim.RunAsync("mode", "program", "--yes", "--fins");
        JsonElement status = (await sim.RunAsync("status", "--fins", "--json")).Json();

        mode.ExitCode.Should().Be(0, mode.ToString());
        sim.Plc.Mode.Should().Be(PlcMode.Program);
        status.GetProperty("mode").GetString().Should().Be("PROGRAM");
    }
}
