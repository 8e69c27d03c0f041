using System.Diagnostics;
using System.Diagnostics.Metrics;
using System.Globalization;
using System.Text;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Statistics;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Writes;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The link polls through the read planner: per unit and interval (a scan class) one planned watch of every group and
/// tag-file row, in the fewest commands (QQ where the unit has it), each group's words in one command, each tag with its
/// own value, quality and log. Against simulators that emulate the time a 9600 bps line takes to carry their answers.
/// </summary>
public sealed class PlannedPollingTests(ITestOutputHelper output) : IDisposable
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(60);
    private readonly string _directory = Directory.CreateTempSubdirectory("ohl-planned-").FullName;
    private readonly CapturingLoggerProvider _logs = new();

    public void Dispose()
    {
        output.WriteLine(string.Join(Environment.NewLine, _logs.Entries.Where(e => e.Level >= LogLevel.Information && e.EventId.Id != GatewayLog.Events.Values).Select(e => $"{e.Time:HH:mm:ss.fff} {e.Level} [{e.EventId.Id}] {e.Message}")));
        Directory.Delete(_directory, recursive: true);
    }

    [Fact]
    public async Task A_Kepware_file_of_100_scattered_words_and_bits_at_1_s_on_a_9600_line_is_read_every_second_with_a_few_commands_a_cycle()
    {
        // The same export on two lines of their own, polled side by side: with QQ (automatic: the CS/CJ names its model
        // to MM) and with area reads only.
        Row[] rows = ScatteredRows(100, seed: 7);
        string file = Path.Combine(_directory, "tags.csv");
        await File.WriteAllTextAsync(file, Csv(rows, scanRateMs: 1000));
        VirtualPlc qqPlc = Plc(rows);
        VirtualPlc areaPlc = Plc(rows);
        await using RecordingSimulator qq = await RecordingSimulator.StartAsync(qqPlc);
        await using RecordingSimulator area = await RecordingSimulator.StartAsync(areaPlc);
        var config = new Dictionary<string, string?>();
        Link(config, "qq", qq.Port, file);
        Link(config, "area", area.Port, file);
        config["HostLink:Links:area:UseCompoundRead"] = "Off";
        var outputs = new RecordingOutput();
        using IHost host = TestGatewayHost.Build(config, _logs, TimeSpan.FromSeconds(10), s => s.AddSingleton<ITagOutput>(outputs));
        using var cycles = new MetricCollector<double>(host.Services.GetRequiredService<IMeterFactory>(), "OmronHostLink.Gateway", LinkStatistics.CycleDurationName);
        await host.StartAsync();
        try
        {
            // The QQ link reads by area until the PLC names its model, then with one QQIR (and an RG for the completion
            // flags). Eight cycles of that plan, measured.
            await Eventually(() => QqPlanned(outputs) >= 0, "the QQ link plans QQ once MM named the model");
            await Eventually(() => outputs.Events.Skip(QqPlanned(outputs) + 1).OfType<ScanCycle>().Count(c => c.Link == "qq") >= 9, "nine cycles of the QQ plan");
            await Eventually(() => outputs.Cycles.Count(c => c.Link == "area") >= 3, "three cycles of the area reads");
        }
        finally
        {
            await host.StopAsync();
        }

        // Every tag of the QQ link read every second (mean time between reads ≤ 1.1 s), with its value.
        TagChange[] good = GoodAfter(outputs, "qq", QqPlanned(outputs));
        foreach (IGrouping<string, TagChange> tag in good.GroupBy(t => t.Tag))
        {
            DateTimeOffset[] times = tag.Select(t => t.Time).Order().ToArray();
            times.Length.Should().BeGreaterThan(5, "{0} is read every cycle", tag.Key);
            double mean = (times[^1] - times[0]).TotalSeconds / (times.Length - 1);
            mean.Should().BeLessThanOrEqualTo(1.1, "{0} is read at its 1 s scan rate", tag.Key);
        }

        good.Select(t => t.Tag).Distinct().Should().HaveCount(rows.Length);
        foreach (string link in new[] { "qq", "area" })
        {
            foreach (Row row in rows)
            {
                TagChange last = outputs.Tags.Last(t => t.Link == link && t.Tag == row.Name && t.Quality == TagQuality.Good);
                Convert.ToInt64(last.Value, CultureInfo.InvariantCulture).Should().Be(row.Expected, "{0}/{1} ({2}) reads what the PLC holds", link, row.Name, row.Address);
            }
        }

        // The PLC sees a handful of commands a cycle, those of the plan: one QQIR, and RG reads of the timers' completion
        // flags (the 95 words and bits, each alone, would be 90 area reads).
        LinkStatistics statistics = host.Services.GetRequiredService<LinkStatistics>();
        ScanClassStatistics qqClass = statistics.Unit("qq", 0)!.ScanClasses.Should().ContainSingle().Subject;
        qqClass.Reads.Should().BeLessThanOrEqualTo(8);
        string[] frames = qq.Received.SkipWhile(f => !f.StartsWith("@00QQIR", StringComparison.Ordinal)).Where(f => f.StartsWith('@')).ToArray();
        int qqCycles = frames.Count(f => f.StartsWith("@00QQIR", StringComparison.Ordinal));
        qqCycles.Should().BeGreaterThan(5);
        frames.Should().OnlyContain(f => f.StartsWith("@00QQIR", StringComparison.Ordinal) || f.StartsWith("@00RG", StringComparison.Ordinal));
        ((double)frames.Length / qqCycles).Should().BeLessThanOrEqualTo(qqClass.Reads, "a cycle is its plan's reads ({0})", string.Join(" ", frames.Take(12).Select(RecordingSimulator.Header)));

        // The plan is in the log at start, with the area link's warning that it cannot keep 1 s on this line.
        _logs.WithEvent(GatewayLog.Events.LinkPlanned).Should().HaveCount(2);
        _logs.WithEvent(GatewayLog.Events.ScanCannotFit).Should().ContainSingle().Which["Link"].Should().Be("area");
        _logs.WithEvent(GatewayLog.Events.ScanPlanned).Should().Contain(e => (string?)e["Link"] == "qq" && ((string)e["Plan"]!).Contains("1 QQIR of", StringComparison.Ordinal));

        // The statistics and the metrics carry each scan class's plan and measured cycle time. The simulator emulates
        // the time of its answers on the line, not of the commands, so the area reads' cycles take less than the plan,
        // which counts both ways, and more than the answers' share of it.
        qqClass.Tags.Should().Be(rows.Length);
        qqClass.IntervalMs.Should().Be(1000);
        // The plan fits the interval; the measured cycle is printed (on a loaded test machine it grows with the load, so
        // the benchmark measures it: docs/performance.md).
        output.WriteLine($"qq scan class: plan {qqClass.EstimatedCycleMs:0} ms a cycle, measured average {qqClass.AverageCycleMs:0} ms");
        qqClass.EstimatedCycleMs.Should().BeLessThan(1000, "the plan of 95 tags fits a 1 s interval at 9600 bps");
        qqClass.AverageCycleMs.Should().BePositive();
        ScanClassStatistics areaClass = statistics.Unit("area", 0)!.ScanClasses.Should().ContainSingle().Subject;
        areaClass.Reads.Should().BeGreaterThan(20);
        areaClass.EstimatedCycleMs.Should().BeGreaterThan(1000);
        areaClass.AverageCycleMs!.Value.Should().BeGreaterThan(areaClass.EstimatedCycleMs * 0.4);
        areaClass.Overruns.Should().BeGreaterThan(0);
        cycles.GetMeasurementSnapshot().Should().Contain(m => (string)m.Tags["hostlink.link.name"]! == "area" && (double)m.Tags["hostlink.scan.interval"]! == 1.0);
    }

    [Fact]
    public async Task A_unit_and_interval_is_one_scan_class_and_a_group_of_several_words_stays_one_snapshot()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0, 1] });
        plc.WriteWords("D100", [.. Enumerable.Range(1, 10).Select(i => (ushort)i)]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);

        // Unit 0 at 1 s: a recipe of ten words and scattered single words QQ reads with it; unit 0 at 100 ms; unit 1 at 1 s.
        MqttGatewayConfig.Group(config, "recipe", "D100", "word", count: 10, intervalMs: 1000);
        foreach (int word in new[] { 500, 900, 1300, 1700, 2100 })
        {
            MqttGatewayConfig.Group(config, $"w{word}", $"D{word}", "word", intervalMs: 1000);
        }

        MqttGatewayConfig.Group(config, "fast", "D3000", "word", intervalMs: 100);
        MqttGatewayConfig.Group(config, "other", "D100", "word", intervalMs: 1000, unit: 1);
        var outputs = new RecordingOutput();
        using IHost host = TestGatewayHost.Build(config, _logs, TimeSpan.FromSeconds(10), s => s.AddSingleton<ITagOutput>(outputs));
        await host.StartAsync();
        try
        {
            await Eventually(() => simulator.Received.Count(f => f.StartsWith("@00QQIR", StringComparison.Ordinal)) >= 2, "unit 0's 1 s class reads with QQ");
        }
        finally
        {
            await host.StopAsync();
        }

        LogEntry planned = _logs.WithEvent(GatewayLog.Events.LinkPlanned).Should().ContainSingle().Subject;
        planned["Classes"].Should().Be(3);
        planned["Tags"].Should().Be(8);
        _logs.WithEvent(GatewayLog.Events.ScanPlanned).Select(e => ((int)e["Unit"]!, (string)e["Interval"]!)).Distinct()
            .Should().BeEquivalentTo([(0, "1 s"), (0, "100 ms"), (1, "1 s")]);

        // The recipe's ten words are always read by one command: one RD of all ten, or all ten registered for one QQIR.
        IReadOnlyList<string> received = simulator.Received;
        HashSet<string> registered = Registered(received);
        string register = string.Join(" ", registered.Order());
        bool allInQq = Enumerable.Range(100, 10).All(w => registered.Contains($"D{w}"));
        bool noneInQq = Enumerable.Range(100, 10).All(w => !registered.Contains($"D{w}"));
        (allInQq || noneInQq).Should().BeTrue("the recipe's words are read together ({0})", register);
        if (noneInQq)
        {
            received.Should().Contain(f => f.StartsWith("@00RD01000010", StringComparison.Ordinal));
        }

        string[] partial = received.Where(f => f.StartsWith("@00RD", StringComparison.Ordinal) && f.Substring(5, 8) != "01000010")
            .Where(f => int.Parse(f.AsSpan(5, 4), CultureInfo.InvariantCulture) is >= 100 and < 110)
            .ToArray();
        partial.Should().BeEmpty("no read takes part of the recipe");
        outputs.Tags.Last(t => t.Tag == "recipe" && t.Quality == TagQuality.Good).Value.Should().BeEquivalentTo(Enumerable.Range(1, 10).Select(i => (ushort)i));

        // The three classes share the line: each expects its own time on it and its waits for the others' reads.
        ScanClassStatistics[] classes = [.. host.Services.GetRequiredService<LinkStatistics>().Link("plc").ScanClasses];
        classes.Should().HaveCount(3).And.OnlyContain(c => c.LineTimeMs > 0 && c.EstimatedCycleMs >= c.LineTimeMs);
        _logs.WithEvent(GatewayLog.Events.ScanPlanned).Should().OnlyContain(e => (double)e["CycleMs"]! >= (double)e["LineMs"]!);
    }

    [Fact]
    public async Task A_write_goes_through_the_links_client_between_two_reads_and_the_next_cycle_publishes_the_new_value()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D500", [5]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        MqttGatewayConfig.Group(config, "setpoint", "D500", intervalMs: 200, writable: true);
        MqttGatewayConfig.Group(config, "level", "D700", intervalMs: 200);
        MqttGatewayConfig.Group(config, "flow", "D900", intervalMs: 200);
        var outputs = new RecordingOutput();

        // The write path the MQTT and Sparkplug outputs use (OpenLinks, the catalogue), without a broker.
        using IHost host = TestGatewayHost.Build(config, _logs, TimeSpan.FromSeconds(10), s => s.AddOutputServices().AddSingleton<ITagOutput>(outputs));
        await host.StartAsync();
        try
        {
            await Eventually(() => outputs.Plans.Any(p => p.Description.Contains("QQIR", StringComparison.Ordinal)) && simulator.Received.Count(f => f.StartsWith("@00QQIR", StringComparison.Ordinal)) >= 2, "the class reads with QQ");
            var writer = new TagWriter(host.Services.GetRequiredService<OpenLinks>());
            TagDefinition setpoint = host.Services.GetRequiredService<TagCatalog>().Find("plc", 0, "setpoint")!;

            TagWriteOutcome outcome = await writer.WriteAsync(setpoint, System.Text.Json.JsonDocument.Parse("1234").RootElement, element: null, CancellationToken.None);

            outcome.Status.Should().Be(TagWriteStatus.Done, outcome.Error);
            int written = outputs.Events.Count;
            await Eventually(() => outputs.Events.Skip(written).OfType<TagChange>().Any(t => t.Tag == "setpoint" && Equals(t.Value, (short)1234)), "the new value is published");
            object[] after = [.. outputs.Events.Skip(written)];
            int published = Array.FindIndex(after, e => e is TagChange { Tag: "setpoint" } t && Equals(t.Value, (short)1234));
            after.Take(published).OfType<ScanCycle>().Count().Should().BeLessThanOrEqualTo(1, "the cycle after the write reads the new value (one under way may end first)");
        }
        finally
        {
            await host.StopAsync();
        }

        plc.ReadWords("D500", 1).Should().Equal([(ushort)1234]);
        string[] frames = [.. simulator.Received.Where(f => f.StartsWith('@'))];
        int write = Array.FindIndex(frames, f => f.StartsWith("@00WD0500", StringComparison.Ordinal));
        write.Should().BePositive();
        frames.Skip(write + 1).Should().Contain(f => f.StartsWith("@00QQIR", StringComparison.Ordinal), "the registration stands: the next read is a QQIR");
    }

    [Fact]
    public async Task A_group_the_PLC_refuses_is_read_on_its_own_until_it_reads_again_and_the_others_keep_their_values()
    {
        // The PLC answers RH with IC: the holding word's group fails; the DM groups of the same scan class read on.
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [11]);
        plc.WriteWords("D200", [22]);
        plc.WriteWords("H10", [33]);
        plc.Options.RefusedCommands = ["RH"];
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["HostLink:Links:plc:UseCompoundRead"] = "Off";
        MqttGatewayConfig.Group(config, "a", "D100", intervalMs: 50);
        MqttGatewayConfig.Group(config, "holding", "H10", intervalMs: 50);
        MqttGatewayConfig.Group(config, "b", "D200", intervalMs: 50);
        var outputs = new RecordingOutput();
        using IHost host = TestGatewayHost.Build(config, _logs, TimeSpan.FromSeconds(10), s => s.AddSingleton<ITagOutput>(outputs));
        await host.StartAsync();
        try
        {
            await Eventually(() => _logs.WithEvent(GatewayLog.Events.ScanSplit).Count == 1, "the scan class is split");
            int before = outputs.Tags.Count;
            await Eventually(() => outputs.Tags.Skip(before).Count(t => t.Tag == "a" && t.Quality == TagQuality.Good) >= 5 && outputs.Tags.Skip(before).Count(t => t.Tag == "b" && t.Quality == TagQuality.Good) >= 5, "the others read on");
            outputs.Tags.Skip(before).Where(t => t.Tag is "a" or "b").Should().OnlyContain(t => t.Quality == TagQuality.Good);
            outputs.Tags.Last(t => t.Tag == "holding").Quality.Should().Be(TagQuality.Stale);
            LogEntry failed = _logs.WithEvent(GatewayLog.Events.GroupFailed).Should().ContainSingle("once per distinct failure").Subject;
            failed["Group"].Should().Be("holding");
            _logs.WithEvent(GatewayLog.Events.ScanSplit).Single().Message.Should().Be("link plc: unit 0 every 50 ms: 1 of 3 tag(s) cannot be read (holding); they are read on their own until they read again, the others together");
            _logs.WithEvent(GatewayLog.Events.UnitDown).Should().BeEmpty("the PLC answers");

            // The PLC takes RH again: the group reads, and joins its class.
            plc.Options.RefusedCommands = [];
            await Eventually(() => _logs.WithEvent(GatewayLog.Events.ScanRejoined).Count == 1, "the group rejoins its class");
            await Eventually(() => outputs.Tags.Any(t => t.Tag == "holding" && t.Quality == TagQuality.Good && Equals(t.Value, (short)33)), "the holding word is read");
            int from = simulator.Received.Count;
            await Eventually(() => simulator.Received.Skip(from).Count(f => RecordingSimulator.Header(f) == "RH") >= 3, "the class reads the holding word again");
        }
        finally
        {
            await host.StopAsync();
        }

        _logs.WithEvent(GatewayLog.Events.GroupRecovered).Should().ContainSingle().Which["Group"].Should().Be("holding");
        _logs.WithEvent(GatewayLog.Events.GroupCrashed).Should().BeEmpty();
    }

    [Fact]
    public async Task A_scan_class_that_cannot_keep_its_interval_is_told_at_start_and_once_when_it_overruns_with_the_measured_period()
    {
        // One RD of 100 words at 9600 bps takes about half a second of answer on the line; the group wants 100 ms.
        var plc = new VirtualPlc(new VirtualPlcOptions { BaudRate = 9600 });
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        var config = new Dictionary<string, string?>();
        Link(config, "slow", simulator.Port, file: null);
        config["HostLink:Links:slow:Groups:block:Address"] = "D0";
        config["HostLink:Links:slow:Groups:block:Count"] = "100";
        config["HostLink:Links:slow:Groups:block:Interval"] = "100ms";
        config["HostLink:Links:slow:Groups:block:Log"] = "OnChange";
        using IHost host = TestGatewayHost.Build(config, _logs, TimeSpan.FromSeconds(10));
        await host.StartAsync();
        try
        {
            await Eventually(() => _logs.WithEvent(GatewayLog.Events.ScanOverrun).Count == 1, "the sustained overrun is told");
        }
        finally
        {
            await host.StopAsync();
        }

        LogEntry cannotFit = _logs.WithEvent(GatewayLog.Events.ScanCannotFit).Should().ContainSingle().Subject;
        double estimated = (double)cannotFit["EstimatedMs"]!;
        estimated.Should().BeGreaterThan(400);
        LogEntry overrun = _logs.WithEvent(GatewayLog.Events.ScanOverrun).Should().ContainSingle("once per episode").Subject;
        overrun.Level.Should().Be(LogLevel.Warning);
        overrun["Interval"].Should().Be("100 ms");
        ((double)overrun["PeriodMs"]!).Should().BeGreaterThan(estimated * 0.4, "the measured period, about a cycle's time on the line");
        overrun.Message.Should().StartWith("link slow: unit 0's 1 tag(s) every 100 ms are read every ");
    }

    private static int QqPlanned(RecordingOutput outputs)
    {
        IReadOnlyList<object> events = outputs.Events;
        for (int i = 0; i < events.Count; i++)
        {
            if (events[i] is ScanPlan { Link: "qq" } plan && plan.Description.Contains("QQIR", StringComparison.Ordinal))
            {
                return i;
            }
        }

        return -1;
    }

    private static TagChange[] GoodAfter(RecordingOutput outputs, string link, int index)
        => index < 0 ? [] : outputs.Events.Skip(index + 1).OfType<TagChange>().Where(t => t.Link == link && t.Quality == TagQuality.Good).ToArray();

    private static void Link(Dictionary<string, string?> config, string name, int port, string? file)
    {
        string l = $"HostLink:Links:{name}:";
        config[l + "Tcp"] = $"127.0.0.1:{port}";
        config[l + "Serial:BaudRate"] = "9600";
        config[l + "TurnaroundAllowance"] = Allowances.LosslessLineText;
        config[l + "Backoff:Initial"] = "00:00:00.100";
        config[l + "Backoff:Max"] = "00:00:00.200";
        if (file is not null)
        {
            config[l + "TagFiles:0:Path"] = file;
            config[l + "TagFiles:0:Format"] = "Kepware";
            config[l + "TagFiles:0:Log"] = "OnChange";
        }
    }

    /// <summary>One row of the export, and the value the PLC holds for it.</summary>
    private sealed record Row(string Name, string Address, string Type, PlcArea Area, int Word, int Bit, long Expected);

    /// <summary>Scattered single words and bits, as a plant's export lists them: DM, IR, HR and AR words and bits, timers' present values and completion flags.</summary>
    private static Row[] ScatteredRows(int count, int seed)
    {
        var random = new Random(seed);
        var rows = new List<Row>();
        var used = new HashSet<(PlcArea, int, int)>();
        while (rows.Count < count)
        {
            int kind = random.Next(10);
            (PlcArea area, string prefix, int max, string format) = kind switch
            {
                < 5 => (PlcArea.Dm, "DM", 9999, "D4"),
                < 7 => (PlcArea.Cio, "IR", 999, "D3"),
                < 8 => (PlcArea.Holding, "HR", 99, "D2"),
                < 9 => (PlcArea.Auxiliary, "AR", 447, "D2"),
                _ => (PlcArea.Timer, "TC", 999, "D3"),
            };
            int word = random.Next(0, max);
            bool bit = area is PlcArea.Cio or PlcArea.Holding or PlcArea.Auxiliary && random.Next(2) == 0;
            bool flag = area == PlcArea.Timer && random.Next(2) == 0;
            int b = bit ? random.Next(16) : -1;
            if (!used.Add((area, word, flag ? 99 : b)))
            {
                continue;
            }

            string name = $"tag{rows.Count:D3}";
            string address = prefix + word.ToString(format, CultureInfo.InvariantCulture) + (bit ? "." + b.ToString("D2", CultureInfo.InvariantCulture) : "");
            long expected = bit || flag ? rows.Count % 2 : 0x100 + rows.Count;
            rows.Add(new Row(name, address, bit || flag ? "Boolean" : "Word", area, word, flag ? -2 : b, expected));
        }

        return [.. rows];
    }

    /// <summary>A PLC holding each row's expected value (words not named by a row hold their own numbers).</summary>
    private static VirtualPlc Plc(Row[] rows)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { BaudRate = 9600 });
        foreach (Row row in rows)
        {
            if (row.Bit == -2)
            {
                plc.SetFlag(row.Area, row.Word, row.Expected != 0);
            }
            else if (row.Bit >= 0)
            {
                plc.SetBit(row.Area, row.Word, row.Bit, row.Expected != 0);
            }
        }

        foreach (Row row in rows.Where(r => r.Bit == -1))
        {
            plc.WriteWord(row.Area, row.Word, (ushort)row.Expected);
        }

        return plc;
    }

    private static string Csv(IEnumerable<Row> rows, int scanRateMs)
        => KepwareTagExport.Csv(rows.Select(r => (r.Name, r.Address, r.Type)), scanRateMs);

    /// <summary>
    /// The DM words the last QQMR registered: its frames joined (each less its FCS and terminator), its items
    /// (<c>DM  0100CH</c>, ten characters each, comma-separated) read.
    /// </summary>
    private static HashSet<string> Registered(IReadOnlyList<string> received)
    {
        int start = received.Select((f, i) => (f, i)).Last(x => x.f.StartsWith("@00QQMR", StringComparison.Ordinal)).i;
        var text = new StringBuilder();
        for (int i = start; i < received.Count; i++)
        {
            string frame = received[i];
            bool last = frame.EndsWith('*');
            string body = frame[..^(last ? 3 : 2)];
            text.Append(i == start ? body[7..] : body);
            if (last)
            {
                break;
            }
        }

        var items = new HashSet<string>();
        foreach (string item in text.ToString().Split(',').Where(i => i.StartsWith("DM", StringComparison.Ordinal)))
        {
            items.Add("D" + int.Parse(item.AsSpan(4, 4), CultureInfo.InvariantCulture).ToString(CultureInfo.InvariantCulture));
        }

        return items;
    }

    private async Task Eventually(Func<bool> condition, string what)
    {
        var clock = Stopwatch.StartNew();
        while (!condition())
        {
            if (clock.Elapsed > Patience)
            {
                throw new Xunit.Sdk.XunitException($"Timed out waiting until {what}. Log:{Environment.NewLine}{_logs.Dump()}");
            }

            await _logs.NextEntry.WaitAsync(TimeSpan.FromMilliseconds(100)).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }
    }
}
