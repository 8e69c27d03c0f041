using System.Diagnostics;
using System.Text.Json;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>simulate</c>: one PLC per unit number unless shared, a valid MS status, and a readiness signal.</summary>
public sealed class CliSimulateTests
{
    [Fact]
    public async Task Each_unit_is_its_own_plc()
    {
        await using var sim = await InProcessSimulator.StartAsync("--units", "0,1");

        CliResult write = await Cli.RunAsync("write", "D0", "5", "--unit", "0", "--tcp", sim.Endpoint);
        CliResult read = await Cli.RunAsync("read", "D0", "--unit", "1", "--json", "--tcp", sim.Endpoint);
        CliResult mode = await Cli.RunAsync("mode", "run", "--yes", "--unit", "1", "--tcp", sim.Endpoint);
        CliResult status0 = await Cli.RunAsync("status", "--unit", "0", "--json", "--tcp", sim.Endpoint);

        write.ExitCode.Should().Be(0, write.ToString());
        read.Json().GetProperty("values")[0].GetInt32().Should().Be(0, "unit 1 has memory of its own");
        mode.ExitCode.Should().Be(0, mode.ToString());
        status0.Json().GetProperty("mode").GetString().Should().Be("PROGRAM", "unit 1's mode change is its own");
    }

    [Fact]
    public async Task Shared_memory_makes_the_units_one_plc()
    {
        await using var sim = await InProcessSimulator.StartAsync("--units", "0,1", "--shared-memory");

        (await Cli.RunAsync("write", "D0", "5", "--unit", "0", "--tcp", sim.Endpoint)).ExitCode.Should().Be(0);
        CliResult read = await Cli.RunAsync("read", "D0", "--unit", "1", "--json", "--tcp", sim.Endpoint);

        read.Json().GetProperty("values")[0].GetInt32().Should().Be(5);
    }

    [Fact]
    public async Task The_ms_status_low_byte_is_a_valid_program_area_code()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        JsonElement j = (await sim.RunAsync("status", "--json")).Json();

        int word = j.GetProperty("statusWord").GetInt32();
        (word & 0x0F).Should().Be(0, "bits 3-0 are 0");
        ((word >> 4) & 0x7).Should().BeInRange(1, 7, "bits 6-4 name a program area size (000 is none)");
        j.GetProperty("userMemoryWritable").GetBoolean().Should().BeTrue("bit 7: UM not write-protected");
    }

    [Fact]
    public async Task Write_protected_user_memory_clears_bit_7()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        sim.Plc.UserMemoryWriteProtected = true;

        JsonElement j = (await sim.RunAsync("status", "--json")).Json();

        j.GetProperty("userMemoryWritable").GetBoolean().Should().BeFalse();
    }

    [Fact]
    public async Task The_ready_file_appears_once_the_simulator_listens_and_goes_when_it_stops()
    {
        string ready = Path.Combine(Path.GetTempPath(), $"hostlink-ready-{Guid.NewGuid():N}");
        await using HostlinkProcess process = HostlinkProcess.Start("simulate", "--tcp", "127.0.0.1:0", "--ready-file", ready);
        try
        {
            await Eventually.UntilAsync(() => File.Exists(ready) || process.HasExited, "the simulator writes its ready file", () => process.Err);
            File.Exists(ready).Should().BeTrue("the simulator ended before it was ready: " + process.Err);

            // As the README does: read the moment the file is there.
            string endpoint = (await File.ReadAllTextAsync(ready)).Trim();
            CliResult read = await Cli.RunAsync("read", "D0", "--tcp", endpoint);

            read.ExitCode.Should().Be(0, read.ToString());
        }
        finally
        {
            process.Signal(ProgramProcess.SigTerm);
            await process.WaitForExitAsync(TimeSpan.FromSeconds(15));
        }

        process.ExitCode.Should().Be(0);
        File.Exists(ready).Should().BeFalse("the file says the simulator is ready only while it runs");
    }
}

/// <summary><c>hostlink simulate</c> run in this process on an ephemeral loopback port, stopped on dispose.</summary>
internal sealed class InProcessSimulator : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop;
    private readonly Task<int> _run;

    private InProcessSimulator(CancellationTokenSource stop, Task<int> run, string endpoint)
    {
        _stop = stop;
        _run = run;
        Endpoint = endpoint;
    }

    public string Endpoint { get; }

    public static async Task<InProcessSimulator> StartAsync(params string[] args)
    {
        var stdout = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        var stop = new CancellationTokenSource();
        Task<int> run = OmronHostLink.Cli.CliApp.RunAsync(["simulate", "--tcp", "127.0.0.1:0", .. args], output, TextWriter.Null, stop.Token);
        string endpoint = await CliSimulatorCommandTests.WaitForEndpointAsync(() => { lock (output) { return stdout.ToString(); } });
        return new InProcessSimulator(stop, run, endpoint);
    }

    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync();
        (await _run.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0);
        _stop.Dispose();
    }
}
