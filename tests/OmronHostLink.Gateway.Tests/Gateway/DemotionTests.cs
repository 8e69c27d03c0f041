using System.Diagnostics.Metrics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Gateway.Statistics;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// A silent unit on a multidrop line is demoted (Demotion:After silent polls in a row): its tags go comm-error at once,
/// it is left alone but for one presence probe a period, and it is restored when it answers; the unit's state and
/// figures show in the logs, the outputs, the statistics and the metrics. Against a line of two simulated PLCs whose
/// received frames are recorded.
/// </summary>
public sealed class DemotionTests(ITestOutputHelper output)
{
    [Fact]
    public async Task A_silent_unit_is_demoted_probed_once_a_period_and_restored_when_it_answers()
    {
        var present = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        present.WriteWords("D100", [7]);
        var absent = new VirtualPlc(new VirtualPlcOptions { Units = [5] });
        absent.WriteWords("D100", [55]);
        absent.Options.Faults.Drop = 1; // unit 5 is silent
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlcLine([present, absent]));
        // The MQTT test link's timings, without MQTT.
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        // The silent unit's polls must time out: a short allowance (the answering unit's exchanges take milliseconds).
        config["HostLink:Links:plc:TurnaroundAllowance"] = "500ms";
        config["HostLink:Links:plc:Demotion:After"] = "2";
        config["HostLink:Links:plc:Demotion:Period"] = "1s";
        MqttGatewayConfig.Group(config, "present", "D100", intervalMs: 50, unit: 0);
        MqttGatewayConfig.Group(config, "absent", "D100", intervalMs: 50, unit: 5);
        MqttGatewayConfig.Group(config, "absent-too", "D101", intervalMs: 50, unit: 5);
        var logs = new CapturingLoggerProvider();
        var outputs = new RecordingOutput();
        using IHost host = MqttGatewayConfig.Build(config, logs, s => s.AddSingleton<ITagOutput>(outputs));
        using var demoted = new MetricCollector<int>(host.Services.GetRequiredService<IMeterFactory>(), "OmronHostLink.Gateway", LinkStatistics.DemotedName);
        using var demotions = new MetricCollector<long>(host.Services.GetRequiredService<IMeterFactory>(), "OmronHostLink.Gateway", LinkStatistics.DemotionsName);
        await host.StartAsync();
        try
        {
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(GatewayLog.Events.UnitDemoted).Count == 1, "unit 5 is demoted", logs);
            // The log comes first; the outputs hear of it right after, on the poller's thread.
            await MqttGatewayConfig.Eventually(() => outputs.Units.Any(u => u.Unit == 5 && u.State == UnitState.Demoted), "the outputs hear unit 5 demoted", logs);
            LogEntry entry = logs.WithEvent(GatewayLog.Events.UnitDemoted).Single();
            entry["Unit"].Should().Be(5);
            entry.Message.Should().StartWith("link plc: PLC unit 5 demoted after 2 silent polls in a row (").And.EndWith("it is left alone for 1 s between presence probes");

            // Its tags are comm-error, the outputs hear it demoted, and the statistics and metrics say so.
            outputs.Units.Should().ContainEquivalentOf(new UnitReport("plc", 5, UnitState.Demoted, null), o => o.Excluding(r => r.Detail));
            TagChange[] commError = outputs.Tags.Where(t => t.Unit == 5 && t.Quality == TagQuality.CommError).ToArray();
            commError.Select(t => t.Tag).Distinct().Should().BeEquivalentTo(["absent", "absent-too"], "every tag of the unit, not only the one that failed");
            UnitStatistics figures = host.Services.GetRequiredService<LinkStatistics>().Unit("plc", 5)!;
            figures.State.Should().Be("demoted");
            figures.Demoted.Should().BeTrue();
            figures.Demotions.Should().Be(1);
            figures.FailuresByKind.Should().ContainKey("timeout");
            demoted.RecordObservableInstruments();
            demoted.GetMeasurementSnapshot().Should().Contain(m => m.Value == 1 && (int)m.Tags["hostlink.unit"]! == 5 && (string)m.Tags["hostlink.link.name"]! == "plc");
            demoted.GetMeasurementSnapshot().Should().Contain(m => m.Value == 0 && (int)m.Tags["hostlink.unit"]! == 0);
            demotions.GetMeasurementSnapshot().Should().ContainSingle().Which.Value.Should().Be(1);

            // Demoted: only presence probes (TS, one a period) reach unit 5, while unit 0 is polled all along.
            int from = simulator.Received.Count;
            int before = outputs.Tags.Count(t => t.Unit == 0 && t.Quality == TagQuality.Good);
            string[] ToUnit5() => simulator.Received.Skip(from).Where(f => f.StartsWith("@05", StringComparison.Ordinal)).ToArray();
            var window = System.Diagnostics.Stopwatch.StartNew();

            // Three probes are the proof that three periods passed; every frame to unit 5 meanwhile must be a probe.
            await Eventually.UntilAsync(() => ToUnit5().Count(f => RecordingSimulator.Header(f) == "TS") >= 3, "the demoted unit is probed three times");
            string[] toUnit5 = ToUnit5();
            TimeSpan elapsed = window.Elapsed;
            output.WriteLine(string.Join(Environment.NewLine, toUnit5));
            toUnit5.Should().OnlyContain(f => RecordingSimulator.Header(f) == "TS", "nothing but probes");
            toUnit5.Length.Should().BeLessThanOrEqualTo((int)elapsed.TotalSeconds + 2, "one probe a period of 1 s");
            outputs.Tags.Count(t => t.Unit == 0 && t.Quality == TagQuality.Good).Should().BeGreaterThan(before + 10, "unit 0 keeps its rate");
            host.Services.GetRequiredService<LinkStatistics>().Unit("plc", 5)!.Transactions.Should().Be(figures.Transactions, "probes are not transactions and nothing else is sent");

            // Unit 5 answers again: its probe lets the reads through, it is restored, and its values arrive.
            absent.Options.Faults.Drop = 0;
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(GatewayLog.Events.UnitRestored).Count == 1, "unit 5 is restored", logs);
            logs.WithEvent(GatewayLog.Events.UnitRestored).Single().Message.Should().MatchRegex(@"^link plc: PLC unit 5 restored: it answered its presence probe after [\d.]+ s without an answer, and is polled again$");
            await MqttGatewayConfig.Eventually(() => outputs.Tags.Any(t => t.Tag == "absent" && t.Quality == TagQuality.Good && Equals(t.Value, (short)55)), "unit 5's value is read", logs);
            await MqttGatewayConfig.Eventually(() => outputs.Tags.Any(t => t.Tag == "absent-too" && t.Quality == TagQuality.Good), "the unit's other group is read too", logs);
            outputs.Units.Last(u => u.Unit == 5).State.Should().Be(UnitState.Online);
            figures = host.Services.GetRequiredService<LinkStatistics>().Unit("plc", 5)!;
            figures.State.Should().Be("online");
            figures.Demoted.Should().BeFalse();
            figures.Demotions.Should().Be(1);
            demoted.RecordObservableInstruments();
            demoted.GetMeasurementSnapshot().Last(m => (int)m.Tags["hostlink.unit"]! == 5).Value.Should().Be(0);
        }
        finally
        {
            await host.StopAsync();
        }
    }
}
