using System.Diagnostics;
using System.Net;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Gateway.Tests.TagImport;

/// <summary>A Kepware export (TagImport/Samples) as the running gateway's tags, polled from the simulator.</summary>
public sealed class TagFileGatewayTests : IDisposable
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(15);
    private readonly List<CapturingLoggerProvider> _logs = [];

    public void Dispose()
    {
        foreach (CapturingLoggerProvider logs in _logs)
        {
            logs.Dispose();
        }
    }

    private static Dictionary<string, string?> Config(int port, string file, string format = "Kepware") => new()
    {
        ["HostLink:Links:plc:Tcp"] = $"127.0.0.1:{port}",
        ["HostLink:Links:plc:Serial:BaudRate"] = "115200",
        ["HostLink:Links:plc:TurnaroundAllowance"] = Allowances.LosslessLineText,
        ["HostLink:Links:plc:Backoff:Initial"] = "00:00:00.100",
        ["HostLink:Links:plc:Backoff:Max"] = "00:00:00.200",
        ["HostLink:Links:plc:TagFiles:0:Path"] = Path.Combine(AppContext.BaseDirectory, "TagImport", "Samples", file),
        ["HostLink:Links:plc:TagFiles:0:Format"] = format,
        ["HostLink:Links:plc:TagFiles:0:Unit"] = "0",
    };

    private IHost BuildHost(Dictionary<string, string?> config, CapturingLoggerProvider logs)
    {
        _logs.Add(logs);
        return TestGatewayHost.Build(config, logs, TimeSpan.FromSeconds(5));
    }

    private static string? LastValue(CapturingLoggerProvider logs, string group)
        => logs.WithEvent(GatewayLog.Events.Values).Where(e => (string?)e["Group"] == group).Select(e => (string?)e["Values"]).LastOrDefault();

    [Fact]
    public async Task A_Kepware_export_becomes_running_tags_that_read_the_simulators_memory()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [1234]);
        plc.WriteWords("D120", [1, 2, 3, 4]);
        plc.WriteWords("D101", [unchecked((ushort)-5)]);
        plc.WriteWords("D102", [0x0042]);
        plc.WriteWords("H10", [0x0008]);
        plc.WriteWords("D106", [0x7960, 0xFFFE]); // -100000, low word first
        plc.WriteWords("D110", [0x0000, 0x41AC]); // 21.5
        plc.WriteWords("A5", [0x8000]);
        await using var simulator = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, 0));
        await simulator.StartAsync();
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(Config(simulator.EndPoint.Port, "kepware-c200h.csv"), logs);

        await host.StartAsync();
        try
        {
            // Every row of the export, every address form Kepware's Host Link driver documents.
            string[] expected = File.ReadAllLines(Path.Combine(AppContext.BaseDirectory, "TagImport", "Samples", "kepware-c200h.csv"))
                .Skip(1).Select(l => l.Split(',')[0].Trim('"')).ToArray();
            expected.Should().HaveCount(22);
            var clock = Stopwatch.StartNew();
            while (expected.Any(g => LastValue(logs, g) is null) && clock.Elapsed < Patience)
            {
                await logs.NextEntry.WaitAsync(Patience);
            }

            LastValue(logs, "Setpoint").Should().Be("0x04D2", "DM0100 (Word) is D100, 1234, logged as a hex word");
            LastValue(logs, "Offset").Should().Be("-5", "DM0101 (Short) is D101 as int16");
            LastValue(logs, "Batch").Should().Be("42", "DM0102 (BCD) reads 0x0042 as 42");
            LastValue(logs, "Recipe").Should().Be("[0x0001, 0x0002, 0x0003, 0x0004]", "DM0120 [4] (Word Array) is four words");
            expected.Where(g => LastValue(logs, g) is null).Should().BeEmpty("every row of the export is a running tag (HR, AR, LR, IR and TC areas included)");
            LastValue(logs, "HoldBit")!.Should().BeOneOf("1", "True", "true");
            LastValue(logs, "Position").Should().Be("-100000", "DM0106 (Long) is two words, low word first");
            LastValue(logs, "Temperature").Should().Be("21.5", "DM0110 (Float) is a REAL");
            LastValue(logs, "AuxBit")!.Should().BeOneOf("1", "True", "true");
            LastValue(logs, "Aux").Should().Be("0x8000", "AR05 is A5");
        }
        finally
        {
            await host.StopAsync();
        }
    }

    [Fact]
    public async Task A_file_with_bad_rows_stops_the_start_naming_the_file_and_every_bad_line()
    {
        using IHost host = BuildHost(Config(9, "kepware-bad-rows.csv"), new CapturingLoggerProvider());

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        error.Should().NotBeNull();
        string message = string.Join("\n", Messages(error!));
        foreach (int line in new[] { 3, 4, 5, 6, 7, 8, 9, 10 })
        {
            message.Should().Contain($"HostLink:Links:plc:TagFiles:0:Path {Path.Combine(AppContext.BaseDirectory, "TagImport", "Samples", "kepware-bad-rows.csv")}, line {line}:");
        }
    }

    private static IEnumerable<string> Messages(Exception e) => ExceptionMessages.Of(e);
}
