using System.Text.RegularExpressions;

namespace OmronHostLink.Cli.Tests;

/// <summary><c>scan</c>: one short probe per unit number, progress, and plain counts.</summary>
public sealed class CliScanTests
{
    [Fact]
    public async Task An_absent_unit_costs_one_probe_and_no_resynchronisation()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [3]);

        CliResult r = await sim.RunAsync("scan", "--units", "0-7", "--timeout", Cli.ScanTimeout, "--verbose");

        r.ExitCode.Should().Be(0, r.ToString());
        Dictionary<int, int> sent = Enumerable.Range(0, 8).ToDictionary(u => u, u => Frames(r, u));
        foreach (int absent in new[] { 0, 1, 2, 4, 5, 6, 7 })
        {
            sent[absent].Should().Be(1, "unit {0} is absent: one probe, no model read and no TS fences ({1})", absent, r.Err);
        }

        sent[3].Should().Be(3, "the unit that answers gets the probe, MM and MS: {0}", r.Err);
        r.Out.Should().Contain("Unit 03");
    }

    [Fact]
    public async Task A_silent_unit_before_a_present_one_does_not_hide_it()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [1, 2]);

        CliResult r = await sim.RunAsync("scan", "--units", "0-3", "--timeout", Cli.ScanTimeout, "--json");

        r.ExitCode.Should().Be(0, r.ToString());
        r.Json().GetProperty("units").EnumerateArray().Select(u => u.GetProperty("unit").GetInt32()).Should().Equal(1, 2);
    }

    [Fact]
    public async Task Scan_shows_progress_on_stderr()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0, 2]);

        CliResult r = await sim.RunAsync("scan", "--units", "0-3", "--timeout", Cli.ScanTimeout);

        r.ExitCode.Should().Be(0, r.ToString());
        r.Err.Should().Contain("Scanning 4 unit numbers");
        r.Err.Should().Contain("2 units answer");
    }

    [Theory]
    [InlineData("5", "probed 1 unit number)")]
    [InlineData("5-6", "probed 2 unit numbers)")]
    public async Task Counts_are_singular_or_plural(string units, string expected)
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("scan", "--units", units, "--timeout", "30ms");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Err.Should().Contain(expected);
    }

    [Fact]
    public async Task An_empty_scan_in_json_is_one_document_with_the_error()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("scan", "--units", "4-5", "--timeout", "30ms", "--json");

        r.ExitCode.Should().Be(4, r.ToString());
        r.Json().GetProperty("units").GetArrayLength().Should().Be(0);
        r.Json().GetProperty("error").GetProperty("kind").GetString().Should().Be("timeout");
    }

    [Fact]
    public async Task One_unit_answering_is_one_unit()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);

        CliResult r = await sim.RunAsync("scan", "--units", "0-1", "--timeout", Cli.ScanTimeout);

        r.Err.Should().Contain("1 unit answers");
    }

    [Fact]
    public async Task A_client_probe_reports_presence_and_keeps_the_link_in_step()
    {
        await using var sim = await SimulatedPlc.StartAsync(units: [0]);
        (string host, int port) = OmronHostLink.Transports.TcpTransport.ParseEndpoint(sim.Endpoint);
        await using HostLinkClient client = HostLinkClient.ForTcp(host, port, new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine });
        sim.Plc.WriteWord(PlcArea.Dm, 0, 42);

        // Only the absent unit's probe waits a short time: its deadline is what tells it is absent.
        TimeSpan? absent = await client.Unit(9).ProbeAsync(TimeSpan.FromMilliseconds(150));
        TimeSpan? present = await client.ProbeAsync();
        ushort value = await client.ReadWordAsync("D0");

        absent.Should().BeNull();
        present.Should().NotBeNull();
        value.Should().Be(42);
    }

    /// <summary>Command frames sent to <paramref name="unit"/> (from the --verbose trace).</summary>
    private static int Frames(CliResult r, int unit)
        => Regex.Matches(r.Err, $@">> @{unit:D2}[A-Z]{{2}}").Count;
}
