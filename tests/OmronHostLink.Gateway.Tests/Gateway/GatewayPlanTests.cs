using OmronHostLink.Gateway.Tests.Telemetry;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// <c>--plan</c>: the configuration checked as for a start, then each link's scan classes and their reads written out,
/// without a PLC: the plans the gateway starts with (tag files included).
/// </summary>
public sealed class GatewayPlanTests
{
    [Fact]
    public async Task Plan_writes_each_links_scan_classes_and_their_reads_and_asks_no_plc()
    {
        string file = Path.Combine(AppContext.BaseDirectory, "TagImport", "Samples", "kepware-c200h.csv");
        await using GatewayProcess process = GatewayProcess.Start(
        [
            "--plan",
            "--Logging:LogLevel:Default=Warning",
            // Nothing listens on port 9: the plan needs no PLC.
            "--HostLink:Links:cs1:Tcp=127.0.0.1:9",
            "--HostLink:Links:cs1:Model=CS1",
            "--HostLink:Links:cs1:Groups:a:Address=D100",
            "--HostLink:Links:cs1:Groups:b:Address=D500",
            "--HostLink:Links:cs1:Groups:c:Address=D900",
            "--HostLink:Links:cs1:Groups:fast:Address=D0",
            "--HostLink:Links:cs1:Groups:fast:Interval=100ms",
            "--HostLink:Links:c200h:Tcp=127.0.0.1:9",
            "--HostLink:Links:c200h:Model=C200H",
            $"--HostLink:Links:c200h:TagFiles:0:Path={file}",
        ]);
        (await process.WaitForExitAsync(TimeSpan.FromSeconds(60))).Should().Be(0, process.Output);

        string[] lines = process.Out.Split('\n', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        lines.Should().Contain(l => l.StartsWith("link cs1: 4 tag(s) in 2 scan class(es) on 9600 bps, ", StringComparison.Ordinal) && l.EndsWith(" % of the line's time", StringComparison.Ordinal));
        lines.Should().Contain(l => l.StartsWith("unit 0 every 1 s: 3 tag(s) in 1 read (1 QQIR of 3 items), ", StringComparison.Ordinal) && l.EndsWith(" of its interval", StringComparison.Ordinal));
        lines.Should().Contain(l => l.StartsWith("unit 0 every 100 ms: 1 tag(s) in 1 read (1 C-mode area read), ", StringComparison.Ordinal));
        lines.Should().Contain("unit 00 C-mode QQIR × 3");

        // The C200H has no QQ: its export's rows are read by area, one scan class a scan rate.
        lines.Should().Contain(l => l.StartsWith("link c200h: 22 tag(s) in ", StringComparison.Ordinal));
        lines.SkipWhile(l => !l.StartsWith("link c200h", StringComparison.Ordinal)).TakeWhile(l => !l.StartsWith("link cs1", StringComparison.Ordinal))
            .Should().NotContain(l => l.Contains("QQIR", StringComparison.Ordinal));
    }
}
