using System.Text.Json;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// The statistics topics: per unit and per link, retained, refreshed every <c>Mqtt:StatisticsInterval</c> and at once
/// when a unit is demoted. A line of two units, one of them silent; Mosquitto on loopback.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttStatisticsTests(ITestOutputHelper output)
{
    [Fact]
    public async Task Each_unit_and_the_link_publish_their_figures_retained_and_a_demotion_at_once()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var present = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        present.WriteWords("D100", [7]);
        var absent = new VirtualPlc(new VirtualPlcOptions { Units = [5] });
        absent.Options.Faults.Drop = 1;
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlcLine([present, absent]));
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker);
        config["Mqtt:StatisticsInterval"] = "1s";
        // The silent unit's polls must time out: a short allowance (the answering unit's exchanges take milliseconds), but
        // not so short that a full test run's load holds the answering unit's answer past it (500 ms once did).
        config["HostLink:Links:plc:TurnaroundAllowance"] = "1s";
        config["HostLink:Links:plc:Demotion:After"] = "2";
        config["HostLink:Links:plc:Demotion:Period"] = "30s";
        MqttGatewayConfig.Group(config, "present", "D100", intervalMs: 50, unit: 0);
        MqttGatewayConfig.Group(config, "absent", "D100", intervalMs: 50, unit: 5);
        string prefix = $"{MqttGatewayConfig.Prefix}/plc/status";
        await using TestSubscriber live = await TestSubscriber.ConnectAsync(broker, [prefix + "/#"]);
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        await host.StartAsync();
        try
        {
            // Unit 5's demotion is published when it happens, not an interval later.
            await live.WaitUntilAsync(ms => ms.Any(m => m.Topic == prefix + "/5" && Json(m).GetProperty("state").GetString() == "demoted"), "unit 5's demotion is published");
            LogEntry demoted = logs.WithEvent(GatewayLog.Events.UnitDemoted).Single();
            ReceivedMessage demotion = live.Messages.First(m => m.Topic == prefix + "/5" && Json(m).GetProperty("state").GetString() == "demoted");
            DateTimeOffset published = DateTimeOffset.Parse(Json(demotion).GetProperty("time").GetString()!, System.Globalization.CultureInfo.InvariantCulture);
            (published - demoted.Time).Should().BeLessThan(TimeSpan.FromMilliseconds(500), "the state change is published at once");

            // Unit 0 reads: its figures grow from one publication to the next.
            await live.WaitUntilAsync(ms => ms.Count(m => m.Topic == prefix + "/0") >= 3, "unit 0's figures are published every second");
            await live.WaitUntilAsync(ms => ms.Any(m => m.Topic == prefix + "/0" && Json(m).GetProperty("transactions").GetInt64() > 5), "unit 0's published figures count its reads");

            await using TestSubscriber late = await TestSubscriber.ConnectAsync(broker, [prefix + "/#"]);
            await late.WaitUntilAsync(ms => new[] { "/0", "/5", "/statistics" }.All(t => ms.Any(m => m.Topic == prefix + t)), "the figures are retained");
            late.Messages.Where(m => m.Topic.StartsWith(prefix + "/", StringComparison.Ordinal)).GroupBy(m => m.Topic).Select(g => g.First())
                .Should().OnlyContain(m => m.Retain, "the first message on each topic is the one the broker kept");
            output.WriteLine(string.Join(Environment.NewLine, late.Messages.Select(m => $"{m.Topic}: {m.Payload}")));

            JsonElement unit0 = Json(late.Messages.Last(m => m.Topic == prefix + "/0"));
            unit0.GetProperty("link").GetString().Should().Be("plc");
            unit0.GetProperty("unit").GetInt32().Should().Be(0);
            unit0.GetProperty("state").GetString().Should().Be("online");
            unit0.GetProperty("demoted").GetBoolean().Should().BeFalse();
            unit0.GetProperty("transactions").GetInt64().Should().BeGreaterThan(5);
            unit0.GetProperty("failures").GetInt64().Should().Be(0);
            unit0.GetProperty("retries").GetInt64().Should().Be(0);
            unit0.GetProperty("lastResponseMs").GetDouble().Should().BeGreaterThan(0).And.BeLessThan(1000);
            unit0.GetProperty("averageResponseMs").GetDouble().Should().BeGreaterThan(0).And.BeLessThan(1000);
            unit0.GetProperty("since").GetString().Should().MatchRegex(@"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$");

            JsonElement unit5 = Json(late.Messages.Last(m => m.Topic == prefix + "/5"));
            unit5.GetProperty("state").GetString().Should().Be("demoted");
            unit5.GetProperty("demoted").GetBoolean().Should().BeTrue();
            unit5.GetProperty("demotions").GetInt64().Should().Be(1);
            long unit5Failures = unit5.GetProperty("failures").GetInt64();
            unit5Failures.Should().BeGreaterThanOrEqualTo(2, "two silent polls demote it");
            unit5.GetProperty("failuresByKind").GetProperty("timeout").GetInt64().Should().Be(unit5Failures);
            unit5.GetProperty("retries").GetInt64().Should().BeGreaterThanOrEqualTo(unit5Failures, "ReadRetries 1: each failed read was tried twice");
            unit5.GetProperty("lastResponseMs").ValueKind.Should().Be(JsonValueKind.Null, "unit 5 never answered");

            JsonElement link = Json(late.Messages.Last(m => m.Topic == prefix + "/statistics"));
            link.TryGetProperty("unit", out _).Should().BeFalse();
            link.GetProperty("state").GetString().Should().Be("comm-error");
            link.GetProperty("demoted").GetBoolean().Should().BeTrue("a unit of the link is demoted");
            link.GetProperty("transactions").GetInt64().Should().BeGreaterThanOrEqualTo(unit0.GetProperty("transactions").GetInt64() + unit5.GetProperty("transactions").GetInt64() - 50);
            link.GetProperty("failuresByKind").GetProperty("timeout").GetInt64().Should().Be(unit5Failures, "unit 5 is demoted and no longer polled");
        }
        finally
        {
            await host.StopAsync();
            output.WriteLine(logs.Dump());
        }
    }

    private static JsonElement Json(ReceivedMessage message) => JsonDocument.Parse(message.Payload).RootElement;
}
