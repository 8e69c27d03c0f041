
namespace OmronHostLink.Cli.Tests;

/// <summary>
/// <c>hostlink</c> on a socat pty pair as a new user tries it: the simulator on one end and reads on the other, each a
/// separate process, all with the default 9600 7E2 settings.
/// </summary>
[Trait("Category", "Slow")]
public sealed class CliSerialProcessTests
{
    private static readonly TimeSpan ProcessTimeout = TimeSpan.FromSeconds(60);

    private static readonly string[] Expected = ["D0  0x1234  4660", "D1  0x0001  1", "D2  0x0002  2", "D3  0x0003  3", "D4  0xFFFF  65535"];

    private static string MemoryFile()
    {
        string path = Path.Combine(Path.GetTempPath(), $"ohl-memory-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, """{"D0": ["0x1234", 1, 2, 3, 65535]}""");
        return path;
    }

    private static async Task ReadsD0To4Async(string port, string why)
    {
        CliResult r = await HostlinkProcess.RunAsync(ProcessTimeout, "read", "D0", "5", "--port", port);
        r.ExitCode.Should().Be(0, $"{why}: {r}");
        r.Lines().Should().Equal(Expected, why);
        r.Err.Should().BeEmpty();
    }

    private static async Task<HostlinkProcess> StartSimulatorAsync(string port, string memory)
    {
        HostlinkProcess sim = HostlinkProcess.Start("simulate", "--port", port, "--memory", memory);
        await sim.ExpectOutputAsync($"on {port} 9600 7E2. Ctrl+C stops.", ProcessTimeout);
        return sim;
    }

    [Fact]
    public async Task Three_read_processes_in_a_row_against_one_simulator_process_on_one_socat_pair_with_default_settings()
    {
        string memory = MemoryFile();
        try
        {
            await using var pair = await SocatPtyPair.StartAsync();
            await using HostlinkProcess sim = await StartSimulatorAsync(pair.PathB, memory);

            for (int i = 1; i <= 3; i++)
            {
                await ReadsD0To4Async(pair.PathA, $"read process {i}");
            }

            sim.Signal(ProgramProcess.SigTerm);
            (await sim.WaitForExitAsync(ProcessTimeout)).Should().Be(0, sim.Err);
            sim.Out.Should().Contain("Simulator stopped.");
        }
        finally
        {
            File.Delete(memory);
        }
    }

    [Fact]
    public async Task The_simulator_process_restarted_on_the_same_pty_serves_again_and_outlives_socat_restarting()
    {
        string memory = MemoryFile();
        SocatPtyPair pair = await SocatPtyPair.StartAsync();
        SocatPtyPair? again = null;
        try
        {
            // Stopped and started again on the same pty: the second process opens it with the same default settings.
            HostlinkProcess first = await StartSimulatorAsync(pair.PathB, memory);
            await ReadsD0To4Async(pair.PathA, "first simulator");
            first.Signal(ProgramProcess.SigTerm);
            (await first.WaitForExitAsync(ProcessTimeout)).Should().Be(0, first.Err);
            await first.DisposeAsync();

            await using HostlinkProcess second = await StartSimulatorAsync(pair.PathB, memory);
            await ReadsD0To4Async(pair.PathA, "simulator restarted on the same pty");

            // The line goes away under the running simulator and comes back on the same names.
            await pair.CloseAsync();
            again = await pair.RestartAsync();
            await second.ExpectOutputAsync($"Serving {pair.PathB} 9600 7E2 again.", ProcessTimeout, onStandardError: true);
            second.Err.Should().Contain($"Lost {pair.PathB} 9600 7E2; opening it again when it is back.");
            await ReadsD0To4Async(again.PathA, "after socat restarted under the simulator");
        }
        finally
        {
            File.Delete(memory);
            await pair.DisposeAsync();
            if (again is not null)
            {
                await again.DisposeAsync();
            }
        }
    }

    [Fact]
    public async Task A_missing_port_exits_4_with_one_sentence_that_names_it_once()
    {
        string missing = Path.Combine(Path.GetTempPath(), "no-such-tty-" + Guid.NewGuid().ToString("N"));

        CliResult r = await HostlinkProcess.RunAsync(ProcessTimeout, "read", "D0", "1", "--port", missing);

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Trim().Should().Be($"Cannot open serial port {missing}: it does not exist. Check that the device is plugged in and the path is right (ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id/).");
    }

    [Fact]
    public async Task Ports_lists_only_existing_serial_devices_sorted_and_never_ptys()
    {
        await using var pair = await SocatPtyPair.StartAsync();

        CliResult r = await Cli.RunAsync("ports", "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        string[] names = r.Json().GetProperty("ports").EnumerateArray().Select(p => p.GetString()!).ToArray();
        names.Where(n => !File.Exists(n)).Should().BeEmpty("every listed port exists");
        names.Should().NotContain(n => n.StartsWith("/dev/pts/", StringComparison.Ordinal));
        names.Should().NotContain([pair.PathA, pair.PathB]);
        names.Should().BeInAscendingOrder(StringComparer.Ordinal);
    }
}
