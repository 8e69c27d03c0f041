using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Gateway.Statistics;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>The worker's host end to end, against the simulator over TCP loopback.</summary>
public sealed class GatewayHostTests(ITestOutputHelper output) : IDisposable
{
    private readonly List<CapturingLoggerProvider> _logs = new();

    /// <summary>Every host's log goes to the test output, so a failure can be read in context.</summary>
    public void Dispose()
    {
        foreach (CapturingLoggerProvider logs in _logs)
        {
            output.WriteLine(logs.Dump());
        }
    }

    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);

    /// <summary>
    /// A link named "plc" to the simulator at <paramref name="port"/>, fast timings, no groups yet; the lossless line's
    /// turnaround allowance unless a test of a silent unit gives a short one.
    /// </summary>
    private static Dictionary<string, string?> Link(int port, string allowance = Allowances.LosslessLineText) => new()
    {
        ["HostLink:Links:plc:Tcp"] = $"127.0.0.1:{port}",
        ["HostLink:Links:plc:Serial:BaudRate"] = "115200",
        ["HostLink:Links:plc:TurnaroundAllowance"] = allowance,
        ["HostLink:Links:plc:ReadRetries"] = "1",
        ["HostLink:Links:plc:Tcp:ConnectTimeout"] = "00:00:00.500",
        ["HostLink:Links:plc:Backoff:Initial"] = "00:00:00.100",
        ["HostLink:Links:plc:Backoff:Max"] = "00:00:00.200",
    };

    private static void Group(Dictionary<string, string?> config, string name, string address, string type = "int16", int count = 1, int intervalMs = 50, string log = "EveryPoll", int unit = 0)
    {
        string g = $"HostLink:Links:plc:Groups:{name}:";
        config[g + "Address"] = address;
        config[g + "Type"] = type;
        config[g + "Count"] = count.ToString(System.Globalization.CultureInfo.InvariantCulture);
        config[g + "Interval"] = TimeSpan.FromMilliseconds(intervalMs).ToString();
        config[g + "Log"] = log;
        config[g + "Unit"] = unit.ToString(System.Globalization.CultureInfo.InvariantCulture);
    }

    private IHost BuildHost(Dictionary<string, string?> config, CapturingLoggerProvider logs)
    {
        _logs.Add(logs);
        return TestGatewayHost.Build(config, logs, TimeSpan.FromSeconds(5));
    }

    /// <summary>Waits until <paramref name="condition"/> (about the log) holds, looking again at each new log entry.</summary>
    private static Task Eventually(Func<bool> condition, string what, CapturingLoggerProvider logs)
        => OmronHostLink.Testing.Eventually.UntilAsync(condition, what, logs);

    private static IEnumerable<LogEntry> Values(CapturingLoggerProvider logs, string group)
        => logs.WithEvent(GatewayLog.Events.Values).Where(e => (string?)e["Group"] == group);

    private static async Task<TcpSimulatorHost> StartSimulator(VirtualPlc plc, int port = 0)
    {
        var host = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, port));
        await host.StartAsync();
        return host;
    }

    [Fact]
    public async Task Polls_values_reports_an_outage_once_and_resumes_with_fresh_values()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [11, 22]);
        TcpSimulatorHost simulator = await StartSimulator(plc);
        int port = simulator.EndPoint.Port;
        Dictionary<string, string?> config = Link(port);
        Group(config, "levels", "D100", count: 2);
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        IHostApplicationLifetime lifetime = host.Services.GetRequiredService<IHostApplicationLifetime>();
        await host.StartAsync();
        try
        {
            await Eventually(() => Values(logs, "levels").Any(e => (string?)e["Values"] == "[11, 22]"), "the values are logged", logs);
            LogEntry first = Values(logs, "levels").First();
            first.Level.Should().Be(LogLevel.Information);
            first["Link"].Should().Be("plc");
            first["Unit"].Should().Be(0);
            first["Address"].Should().Be("D100");
            first.Message.Should().Be("plc/levels: unit 0 D100 = [11, 22]");

            // The PLC goes away: one warning, however many poll intervals and retries pass.
            await simulator.StopAsync();
            await Eventually(() => logs.WithEvent(GatewayLog.Events.UnitDown).Count == 1, "the outage is reported", logs);
            // Several backoff periods: the worker keeps retrying (each a "still down" entry) and warns only once.
            await Eventually(() => logs.WithEvent(GatewayLog.Events.UnitStillDown).Count >= 4, "the worker has retried several times", logs);
            logs.WithEvent(GatewayLog.Events.UnitDown).Should().ContainSingle().Which.Level.Should().Be(LogLevel.Warning);
            logs.WithEvent(GatewayLog.Events.UnitDown)[0].Message.Should().StartWith("link plc: PLC unit 0 not answering (");
            logs.WithEvent(GatewayLog.Events.UnitStillDown).Should().NotBeEmpty("the worker keeps trying in the background");
            lifetime.ApplicationStopping.IsCancellationRequested.Should().BeFalse("an outage never stops the host");
            int polledBefore = Values(logs, "levels").Count();

            // The PLC comes back on the same port with a new value.
            plc.WriteWords("D100", [33, 44]);
            await using TcpSimulatorHost restarted = await StartSimulator(plc, port);
            await Eventually(() => Values(logs, "levels").Any(e => (string?)e["Values"] == "[33, 44]"), "polling resumes with fresh values", logs);
            logs.WithEvent(GatewayLog.Events.UnitResumed).Should().ContainSingle().Which.Message.Should().MatchRegex(@"^link plc: PLC unit 0 resumed after \d");
            logs.WithEvent(GatewayLog.Events.UnitDown).Should().ContainSingle();
            Values(logs, "levels").Count().Should().BeGreaterThan(polledBefore);
        }
        finally
        {
            var clock = Stopwatch.StartNew();
            await host.StopAsync();
            clock.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(3));
            await simulator.DisposeAsync();
        }

        logs.WithEvent(GatewayLog.Events.LinkStopped).Should().ContainSingle();
        logs.Entries.Should().NotContain(e => e.Level >= LogLevel.Error, logs.Dump());
    }

    [Fact]
    public async Task A_silent_unit_on_a_multidrop_link_is_reported_once_and_does_not_stop_the_others()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        plc.WriteWords("D100", [7]);
        await using TcpSimulatorHost simulator = await StartSimulator(plc);
        // The silent unit costs its allowance on every attempt, so it is short here; unit 0's outages, should the
        // machine be too busy to answer it in time, are not what this test is about.
        Dictionary<string, string?> config = Link(simulator.EndPoint.Port, allowance: "00:00:00.200");
        Group(config, "present", "D100", unit: 0);
        Group(config, "absent", "D100", unit: 5); // nobody answers unit 5: every read times out
        // Each attempt on the silent unit costs the link about 0.8 s (timeouts, and the library's resynchronisation
        // fence, which it sends to the unit that failed); a realistic backoff leaves the link to unit 0 in between.
        config["HostLink:Links:plc:Backoff:Initial"] = "00:00:00.500";
        config["HostLink:Links:plc:Backoff:Max"] = "00:00:01";
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        try
        {
            await Eventually(() => OfUnit5(GatewayLog.Events.UnitDown).Count == 1, "the silent unit is reported", logs);
            int before = Values(logs, "present").Count();
            await Eventually(
                () => Values(logs, "present").Count() > before + 5 && OfUnit5(GatewayLog.Events.UnitStillDown).Count >= 2,
                "unit 0 is polled several times while unit 5 is retried",
                logs);
            LogEntry down = OfUnit5(GatewayLog.Events.UnitDown).Should().ContainSingle().Subject;
            down["Unit"].Should().Be(5);
            down["Reason"].Should().Be("timeout");
            down.Message.Should().StartWith("link plc: PLC unit 5 not answering (timeout)");
            OfUnit5(GatewayLog.Events.UnitStillDown).Should().NotBeEmpty();
            Values(logs, "present").Count().Should().BeGreaterThan(before + 5, "unit 0 is polled between the attempts on unit 5");
            Values(logs, "absent").Should().BeEmpty();
        }
        finally
        {
            await host.StopAsync();
        }

        List<LogEntry> OfUnit5(int eventId) => logs.WithEvent(eventId).Where(e => e["Unit"] is 5).ToList();
    }

    [Fact]
    public async Task OnChange_logs_only_changes()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D200", [5]);
        await using TcpSimulatorHost simulator = await StartSimulator(plc);
        Dictionary<string, string?> config = Link(simulator.EndPoint.Port);
        Group(config, "watched", "D200", type: "uint16", log: "OnChange");
        Group(config, "ticker", "D201", type: "uint16", log: "EveryPoll");
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        try
        {
            await Eventually(() => Values(logs, "ticker").Count() >= 8, "several polls", logs);
            Values(logs, "watched").Select(e => (string?)e["Values"]).Should().Equal("5");

            plc.WriteWords("D200", [6]);
            await Eventually(() => Values(logs, "watched").Count() == 2, "the change is logged", logs);
            int ticks = Values(logs, "ticker").Count();
            await Eventually(() => Values(logs, "ticker").Count() >= ticks + 8, "several more polls", logs);
            Values(logs, "watched").Select(e => (string?)e["Values"]).Should().Equal("5", "6");
        }
        finally
        {
            await host.StopAsync();
        }
    }

    [Fact]
    public async Task A_group_whose_words_do_not_decode_fails_alone_and_a_timer_flag_reads_as_a_bit()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [0x00A1]); // not BCD
        plc.SetFlag(PlcArea.Timer, 5, true);
        await using TcpSimulatorHost simulator = await StartSimulator(plc);
        Dictionary<string, string?> config = Link(simulator.EndPoint.Port);
        Group(config, "code", "D100", type: "bcd");
        Group(config, "done", "T5", type: "bit", log: "OnChange");
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        try
        {
            await Eventually(() => logs.WithEvent(GatewayLog.Events.GroupFailed).Count == 1 && Values(logs, "done").Any(), "the failure and the flag are logged", logs);
            long transactions = host.Services.GetRequiredService<LinkStatistics>().Unit("plc", 0)!.Transactions;
            await OmronHostLink.Testing.Eventually.UntilAsync(
                () => host.Services.GetRequiredService<LinkStatistics>().Unit("plc", 0)!.Transactions >= transactions + 12, "six more polls of each group", logs);
            LogEntry failed = logs.WithEvent(GatewayLog.Events.GroupFailed).Should().ContainSingle("once per distinct failure").Subject;
            failed.Message.Should().StartWith("plc/code: unit 0 D100 cannot be read: ").And.Contain("0x00A1");
            Values(logs, "done").Single()["Values"].Should().Be("1");
            logs.WithEvent(GatewayLog.Events.UnitDown).Should().BeEmpty("the PLC answers");

            plc.WriteWords("D100", [0x0421]);
            await Eventually(() => Values(logs, "code").Any(e => (string?)e["Values"] == "421"), "the group reads again", logs);
            logs.WithEvent(GatewayLog.Events.GroupRecovered).Should().ContainSingle().Which.Message.Should().Be("plc/code: unit 0 D100 reads again");
        }
        finally
        {
            await host.StopAsync();
        }
    }

    [Fact]
    public async Task Groups_on_one_link_share_it_fairly()
    {
        // Every answer frame waits for a PLC turnaround, as on a real line: the link, not the worker's handling of what
        // it read, is what the groups share. The turns are read from the frames that reach the PLC. The turnaround is long beside a
        // loaded machine's scheduling delays, so a group slow to queue again after its read is mostly back before the
        // other's exchange ends.
        var plc = new VirtualPlc(new VirtualPlcOptions { Turnaround = TimeSpan.FromMilliseconds(25) });
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = Link(simulator.Port);
        // Two groups that want the link all the time (1 ms) and one at 500 ms: the link is saturated.
        Group(config, "big", "D0", type: "word", count: 200, intervalMs: 1);
        Group(config, "small", "D1000", type: "word", intervalMs: 1);
        Group(config, "slow", "D2000", type: "word", intervalMs: 500);
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        try
        {
            // Enough turns of the busy groups to compare, however slowly a loaded machine serves the link.
            await Eventually(() => Values(logs, "slow").Count() >= 5 && BusyTurns().Count(t => t == "big") > 10,
                "the 500 ms group runs repeatedly and the busy groups take more than ten turns", logs);
        }
        finally
        {
            await host.StopAsync();
        }

        // The busy groups take turns: each goes back to the link's gate as soon as its read is done and is served after
        // the other. A group reads twice running only when the other was not back at the gate yet (a busy machine can
        // hold a group back between its read and the next); most of each group's turns come one at a time.
        List<(string Group, int Length)> runs = Runs(BusyTurns());
        foreach (string group in new[] { "big", "small" })
        {
            List<int> lengths = runs.Where(r => r.Group == group).Select(r => r.Length).ToList();
            lengths.Count(l => l == 1).Should().BeGreaterThan(lengths.Count * 2 / 3, "{0} takes its turns one at a time (runs of turns: {1})", group, string.Join(" ", runs.Select(r => $"{r.Group}x{r.Length}")));
        }

        string[] BusyTurns() => simulator.Received
            .Where(f => RecordingSimulator.Header(f) == "RD" && f.Substring(5, 4) is "0000" or "1000")
            .Select(f => f.Substring(5, 4) == "0000" ? "big" : "small")
            .ToArray();

        static List<(string Group, int Length)> Runs(string[] turns)
        {
            var runs = new List<(string Group, int Length)>();
            foreach (string turn in turns)
            {
                if (runs.Count > 0 && runs[^1].Group == turn)
                {
                    runs[^1] = (turn, runs[^1].Length + 1);
                }
                else
                {
                    runs.Add((turn, 1));
                }
            }

            return runs;
        }
    }

    [Fact]
    public async Task Stops_promptly_while_a_read_waits_for_a_silent_plc()
    {
        // A gateway that accepts the connection and never answers; the turnaround allowance is long.
        using var silent = new TcpListener(IPAddress.Loopback, 0);
        silent.Start();
        var accepted = new List<TcpClient>();
        _ = Task.Run(async () =>
        {
            try
            {
                while (true)
                {
                    accepted.Add(await silent.AcceptTcpClientAsync());
                }
            }
            catch (Exception e) when (e is SocketException or ObjectDisposedException)
            {
            }
        });
        Dictionary<string, string?> config = Link(((IPEndPoint)silent.LocalEndpoint).Port);
        config["HostLink:Links:plc:TurnaroundAllowance"] = "00:00:30";
        Group(config, "levels", "D100");
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        await Eventually(() => logs.WithEvent(GatewayLog.Events.LinkStarted).Count == 1, "the link starts", logs);
        await OmronHostLink.Testing.Eventually.UntilAsync(() => Volatile.Read(ref accepted).Count > 0, "the link connects to the silent PLC");

        var clock = Stopwatch.StartNew();
        await host.StopAsync();
        clock.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(2), "the stopping token cancels the pending read");
        logs.WithEvent(GatewayLog.Events.LinkStopped).Should().ContainSingle();
        logs.WithEvent(GatewayLog.Events.UnitDown).Should().BeEmpty();
        foreach (TcpClient c in accepted.ToArray())
        {
            c.Dispose();
        }
    }

    [Fact]
    public async Task The_simulator_section_runs_a_virtual_plc_inside_the_worker()
    {
        int port;
        using (var probe = new TcpListener(IPAddress.Loopback, 0))
        {
            probe.Start();
            port = ((IPEndPoint)probe.LocalEndpoint).Port;
            probe.Stop();
        }

        Dictionary<string, string?> config = Link(port);
        Group(config, "levels", "D100", count: 2);
        Group(config, "name", "D300", type: "string", count: 6, log: "OnChange");
        config["Simulator:Enabled"] = "true";
        config["Simulator:Port"] = port.ToString(System.Globalization.CultureInfo.InvariantCulture);
        config["Simulator:Memory:D100"] = "120, -340";
        config["Simulator:Memory:D300"] = "'MIX-A7'";
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);
        await host.StartAsync();
        try
        {
            await Eventually(() => Values(logs, "levels").Any() && Values(logs, "name").Any(), "both groups are logged", logs);
            Values(logs, "levels").First()["Values"].Should().Be("[120, -340]");
            Values(logs, "name").First()["Values"].Should().Be("\"MIX-A7\"");
        }
        finally
        {
            await host.StopAsync();
        }

        logs.WithEvent(OmronHostLink.Gateway.Simulation.SimulatorLog.Events.Started).Should().ContainSingle();
    }

    public static TheoryData<string, string?, string> BadSettings => new()
    {
        { "HostLink:Links:plc:Groups:g:Address", "D99999", "HostLink:Links:plc:Groups:g:Address" },
        { "HostLink:Links:plc:Groups:g:Address", "", "HostLink:Links:plc:Groups:g:Address is empty" },
        { "HostLink:Links:plc:Groups:g:Address", "D100.03", "HostLink:Links:plc:Groups:g:Address D100.03 names a bit" },
        { "HostLink:Links:plc:Groups:g:Count", "20000", "HostLink:Links:plc:Groups:g:Count" },
        { "HostLink:Links:plc:Groups:g:Type", "flot", "HostLink:Links:plc:Groups:g:Type 'flot' is not one of word, bcd" },
        { "HostLink:Links:plc:Groups:g:Unit", "32", "HostLink:Links:plc:Groups:g:Unit: 32 is not a unit number (0-31)" },
        { "HostLink:Links:plc:Groups:g:Interval", "00:00:00", "HostLink:Links:plc:Groups:g:Interval must be more than 0" },
        { "HostLink:Links:plc:Groups:g:Interval", "2.00:00:00", "HostLink:Links:plc:Groups:g:Interval must be more than 0 and at most 1 day; it is 2.00:00:00" },
        { "HostLink:Links:plc:Backoff:Max", "3.00:00:00", "HostLink:Links:plc:Backoff:Max must be at most 1 day; it is 3.00:00:00" },
        { "HostLink:Links:plc:Groups:g:Log", "Sometimes", "HostLink:Links:plc:Groups:g:Log 'Sometimes' is not EveryPoll or OnChange" },
        { "HostLink:Links:plc:Serial:PortName", "/dev/ttyS0", "HostLink:Links:plc:Tcp: cannot be combined with Serial:PortName" },
        { "HostLink:Links:plc:Tcp", "", "HostLink:Links:plc: no link is set" },
        { "HostLink:Links:plc:Tcp", "gateway", "HostLink:Links:plc:Tcp: 'gateway' is not host:port" },
        { "HostLink:Links:plc:Backoff:Initial", "00:00:00", "HostLink:Links:plc:Backoff:Initial must be more than 0" },
        { "HostLink:Links:plc:Enabled", "false", "HostLink:Links: no enabled link is configured" },
        { "Simulator:Enabled", "true", "Simulator:Memory:D1: 'x' is not a word" },
    };

    [Theory]
    [MemberData(nameof(BadSettings))]
    public async Task Invalid_configuration_fails_at_start_naming_the_field(string key, string? value, string expected)
    {
        Dictionary<string, string?> config = Link(9);
        Group(config, "g", "D100");
        config["Simulator:Memory:D1"] = "x"; // only checked when the simulator is enabled
        config[key] = value;
        var logs = new CapturingLoggerProvider();
        using IHost host = BuildHost(config, logs);

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        error.Should().NotBeNull();
        Messages(error!).Should().Contain(m => m.Contains(expected, StringComparison.Ordinal), $"the message names the field ({string.Join(" | ", Messages(error!))})");
        logs.WithEvent(GatewayLog.Events.LinkStarted).Should().BeEmpty();
    }

    [Fact]
    public async Task A_serial_link_with_bad_line_settings_is_refused_naming_the_setting()
    {
        Dictionary<string, string?> config = Link(9);
        config["HostLink:Links:plc:Tcp"] = null;
        config["HostLink:Links:plc:Serial:PortName"] = "/dev/ttyUSB0";
        config["HostLink:Links:plc:Serial:BaudRate"] = "1234";
        Group(config, "g", "D100");
        using IHost host = BuildHost(config, new CapturingLoggerProvider());

        Exception? error = await Record.ExceptionAsync(() => host.StartAsync());

        Messages(error!).Should().Contain(m => m.Contains("HostLink:Links:plc:Serial:BaudRate", StringComparison.Ordinal));
    }

    private static IEnumerable<string> Messages(Exception e) => ExceptionMessages.Of(e);
}
