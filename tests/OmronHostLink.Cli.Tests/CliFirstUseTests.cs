using System.Text;
using System.Text.Json;
using OmronHostLink.Capture;

namespace OmronHostLink.Cli.Tests;

/// <summary>What a new user meets first: a write refused in RUN mode says how to get past it, CX-Programmer's type names, what the simulator starts as, a trace of the frames.</summary>
public sealed class CliFirstUseTests
{
    [Fact]
    public async Task A_write_refused_in_run_mode_says_how_to_switch_and_the_switch_works()
    {
        await using var sim = await SimulatedPlc.StartAsync(PlcMode.Run);

        CliResult refused = await sim.RunAsync("write", "D0", "1");
        CliResult mode = await sim.RunAsync("mode", "monitor", "--yes");
        CliResult written = await sim.RunAsync("write", "D0", "1");

        refused.ExitCode.Should().Be(3, refused.ToString());
        refused.Err.Should().Contain("Not executable in RUN mode").And.Contain("switch with 'hostlink mode monitor --yes' and the same --port or --tcp, or write with --fins");
        mode.ExitCode.Should().Be(0, mode.ToString());
        written.ExitCode.Should().Be(0, written.ToString());
        sim.Plc.ReadWord(PlcArea.Dm, 0).Should().Be(1);
    }

    [Theory]
    [InlineData("real", "float")]
    [InlineData("REAL", "float")]
    [InlineData("lreal", "double")]
    public async Task CX_Programmers_type_names_are_taken(string name, string type)
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult write = await sim.RunAsync("write", "D200", "21.5", "--as", name);
        CliResult read = await sim.RunAsync("read", "D200", "--as", name, "--json");

        write.ExitCode.Should().Be(0, write.ToString());
        JsonElement j = read.Json();
        j.GetProperty("as").GetString().Should().Be(type);
        j.GetProperty("values")[0].GetDouble().Should().Be(21.5);
        if (type == "float")
        {
            // IEEE 754 single 21.5 is 0x41AC0000, low word first (Omron's order).
            sim.Plc.ReadWords(PlcArea.Dm, 200, 2).Should().Equal(0x0000, 0x41AC);
        }
    }

    [Fact]
    public async Task Simulate_says_its_mode_and_memory_and_in_run_mode_how_to_write()
    {
        var stdout = new StringWriter();
        TextWriter output = TextWriter.Synchronized(stdout);
        using var stop = new CancellationTokenSource();
        Task<int> run = CliApp.RunAsync(["simulate", "--tcp", "127.0.0.1:0", "--mode", "run"], output, TextWriter.Null, stop.Token);
        string endpoint = await CliSimulatorCommandTests.WaitForEndpointAsync(() => { lock (output) { return stdout.ToString(); } });
        await stop.CancelAsync();
        (await run.WaitAsync(TimeSpan.FromSeconds(10))).Should().Be(0);

        string text = stdout.ToString();
        text.Should().Contain("(RUN mode, memory all zero, model code 30)");
        text.Should().Contain($"In RUN mode a CS/CJ refuses C-mode writes (end code 01): switch with 'hostlink mode monitor --yes --tcp {endpoint}', or write with --fins.");
    }

    [Fact]
    public async Task Trace_writes_the_frames_of_a_command_to_a_pcap()
    {
        await using var sim = await SimulatedPlc.StartAsync();
        string trace = Path.Combine(Path.GetTempPath(), $"hostlink-trace-{Guid.NewGuid():N}.pcap");
        try
        {
            CliResult r = await sim.RunAsync("read", "D0", "3", "--trace", trace);

            r.ExitCode.Should().Be(0, r.ToString());
            IReadOnlyList<CapturedFrame> frames = CaptureReader.Read(trace);
            frames.Select(f => (f.Direction, Encoding.ASCII.GetString(f.Bytes))).Should().Equal(
                (LineDirection.ToPlc, "@00RD0000000355*\r"),
                (LineDirection.FromPlc, "@00RD0000000000000056*\r"));
        }
        finally
        {
            File.Delete(trace);
        }
    }

    [Fact]
    public async Task A_trace_file_that_cannot_be_created_is_refused_before_anything_is_sent()
    {
        await using var sim = await SimulatedPlc.StartAsync();

        CliResult r = await sim.RunAsync("read", "D0", "--trace", "/nonexistent-dir/trace.pcap");

        r.ExitCode.Should().Be(2, r.ToString());
        r.Err.Should().StartWith("--trace: cannot create '/nonexistent-dir/trace.pcap'");
    }
}
