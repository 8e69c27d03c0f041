using System.Diagnostics;
using System.Globalization;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// How the groups of one link share it, read from the frames that reach the PLC: one planned watch per unit and
/// interval on the link's one client, whose gate takes waiting reads in turn. The PLC answers after a turnaround, as on
/// a real line, so the link (not the worker's handling of what it read) is what the groups share. The link reads by area
/// (UseCompoundRead Off), so that each group's reads are the RD frames of its words.
/// </summary>
public sealed class LinkSchedulingTests(ITestOutputHelper output) : IAsyncLifetime
{
    private readonly List<CapturingLoggerProvider> _logs = new();
    private RecordingSimulator _simulator = null!;

    public async Task InitializeAsync()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0], Turnaround = TimeSpan.FromMilliseconds(5) });
        _simulator = await RecordingSimulator.StartAsync(plc);
    }

    public async Task DisposeAsync()
    {
        await _simulator.DisposeAsync();
        foreach (CapturingLoggerProvider logs in _logs)
        {
            output.WriteLine(logs.Dump());
        }
    }

    [Fact]
    public async Task Groups_start_in_the_order_configured_and_take_turns_when_all_are_due()
    {
        Dictionary<string, string?> config = Link();
        Group(config, "a", "D0", intervalMs: 1);
        Group(config, "b", "D10", intervalMs: 1);
        Group(config, "c", "D20", intervalMs: 1);

        await RunAsync(config, () => Reads().Count >= 30);

        string[] order = Reads().Select(r => r.Word switch { 0 => "a", 10 => "b", 20 => "c", _ => "?" }).ToArray();
        order.Take(27).Should().Equal(Enumerable.Repeat(new[] { "a", "b", "c" }, 9).SelectMany(x => x), "the groups alternate read for read");
    }

    [Fact]
    public async Task No_group_starves_on_an_overloaded_link()
    {
        // Three groups want a read every millisecond (one of them 120 words, four answer frames): the link can never
        // keep up. A fourth wants one every 500 ms.
        Dictionary<string, string?> config = Link();
        Group(config, "fast", "D0", intervalMs: 1);
        Group(config, "also-fast", "D10", intervalMs: 1);
        Group(config, "slow-read", "D100", count: 120, intervalMs: 1);
        Group(config, "rare", "D500", intervalMs: 500);

        TimeSpan elapsed = await RunAsync(config, () => Reads().Count(r => r.Word == 500) >= 4);

        Dictionary<int, int> counts = Reads().GroupBy(r => r.Word).ToDictionary(g => g.Key, g => g.Count());
        counts[0].Should().BeCloseTo(counts[10], 1);
        counts[100].Should().BeCloseTo(counts[0], 1);
        // The rare group still gets its turn every time it is due.
        counts[500].Should().BeGreaterThanOrEqualTo((int)(elapsed.TotalMilliseconds / 500) - 1);
    }

    [Fact]
    public async Task While_a_unit_is_down_one_of_its_groups_tries_it_and_the_others_wait()
    {
        // The silent unit costs its allowance on every attempt, so it is short here; unit 0's outages, should the machine
        // be too busy to answer it in time, are not what this test is about.
        Dictionary<string, string?> config = Link(allowance: "00:00:00.200");
        // Each attempt on a silent unit costs the link its timeouts and the fence after them (about 0.7 s here).
        config["HostLink:Links:plc:Backoff:Initial"] = "00:00:00.500";
        config["HostLink:Links:plc:Backoff:Max"] = "00:00:00.500";
        config["HostLink:Links:plc:Demotion:After"] = "0"; // retried with the backoff for ever (DemotionTests: demoted)
        Group(config, "present", "D0", intervalMs: 50);
        Group(config, "x", "D100", intervalMs: 50, unit: 5); // nobody answers unit 5
        Group(config, "y", "D200", intervalMs: 50, unit: 5);
        Group(config, "z", "D300", intervalMs: 50, unit: 5);
        CapturingLoggerProvider logs = null!;
        int before = 0;
        await RunAsync(config, () => false, async (l, _) =>
        {
            logs = l;
            // Each group of unit 5 fails once when the outage begins (x, y, z), then only one of them tries again.
            await Eventually(() => OfUnit5(l, GatewayLog.Events.UnitDown).Count == 1 && OfUnit5(l, GatewayLog.Events.UnitStillDown).Count >= 3, l);
            before = Reads().Count;
            int attempts = OfUnit5(l, GatewayLog.Events.UnitStillDown).Count;
            // Three more attempts on the silent unit, and unit 0 polled meanwhile: counted, not timed, so a busy
            // machine only makes the window longer.
            await Eventually(() => OfUnit5(l, GatewayLog.Events.UnitStillDown).Count >= attempts + 3 && Reads().Skip(before).Count(r => r.Unit == 0) > 5, l);
        });

        List<(int Unit, int Word)> during = Reads().Skip(before).ToList();
        during.Where(r => r.Unit == 5).Select(r => r.Word).Distinct().Should().ContainSingle("one group tries the silent unit; the others wait for it to answer");
        during.Count(r => r.Unit == 5).Should().BeGreaterThan(2, "the unit is tried again after each backoff");
        during.Count(r => r.Unit == 0).Should().BeGreaterThan(5, "unit 0 is polled between the attempts");
        OfUnit5(logs, GatewayLog.Events.UnitDown).Should().ContainSingle();

        static List<LogEntry> OfUnit5(CapturingLoggerProvider logs, int eventId) => logs.WithEvent(eventId).Where(e => e["Unit"] is 5).ToList();
    }

    /// <summary>The C-mode word reads (<c>@uuRDwwwwcccc…</c>) the PLC received, in order.</summary>
    private List<(int Unit, int Word)> Reads() => _simulator.Received
        .Where(f => RecordingSimulator.Header(f) == "RD")
        .Select(f => (int.Parse(f.AsSpan(1, 2), CultureInfo.InvariantCulture), int.Parse(f.AsSpan(5, 4), CultureInfo.InvariantCulture)))
        .ToList();

    /// <summary>The link to the simulator; the lossless line's turnaround allowance unless a test of a silent unit gives a short one.</summary>
    private Dictionary<string, string?> Link(string allowance = Allowances.LosslessLineText) => new()
    {
        ["HostLink:Links:plc:Tcp"] = $"127.0.0.1:{_simulator.Port}",
        ["HostLink:Links:plc:Serial:BaudRate"] = "115200",
        ["HostLink:Links:plc:TurnaroundAllowance"] = allowance,
        ["HostLink:Links:plc:ReadRetries"] = "1",
        ["HostLink:Links:plc:Tcp:ConnectTimeout"] = "00:00:00.500",
        ["HostLink:Links:plc:UseCompoundRead"] = "Off",
    };

    private static void Group(Dictionary<string, string?> config, string name, string address, int count = 1, int intervalMs = 50, int unit = 0)
    {
        string g = $"HostLink:Links:plc:Groups:{name}:";
        config[g + "Address"] = address;
        config[g + "Type"] = "word";
        config[g + "Count"] = count.ToString(CultureInfo.InvariantCulture);
        config[g + "Interval"] = TimeSpan.FromMilliseconds(intervalMs).ToString();
        config[g + "Log"] = "OnChange";
        config[g + "Unit"] = unit.ToString(CultureInfo.InvariantCulture);
    }

    /// <summary>Runs the worker until <paramref name="done"/> (and <paramref name="during"/>) and stops it; returns how long it ran.</summary>
    private async Task<TimeSpan> RunAsync(Dictionary<string, string?> config, Func<bool> done, Func<CapturingLoggerProvider, IHost, Task>? during = null)
    {
        var logs = new CapturingLoggerProvider();
        _logs.Add(logs);
        using IHost host = TestGatewayHost.Build(config, logs, TimeSpan.FromSeconds(5));
        var clock = Stopwatch.StartNew();
        await host.StartAsync();
        try
        {
            if (during is not null)
            {
                await during(logs, host);
            }
            else
            {
                await Eventually(done, logs);
            }
        }
        finally
        {
            await host.StopAsync();
        }

        return clock.Elapsed;
    }

    private static Task Eventually(Func<bool> condition, CapturingLoggerProvider logs)
        => OmronHostLink.Testing.Eventually.UntilAsync(condition, "the log shows it", logs);
}
