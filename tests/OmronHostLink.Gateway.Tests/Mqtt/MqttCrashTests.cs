using System.Text.Json;
using OmronHostLink.Gateway.Tests.Telemetry;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// The gateway as a real process, killed with SIGKILL while the broker is down, started again, then the broker back:
/// with the durable queue every change of the outage arrives once and in order; without it, the loss is announced.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttCrashTests(ITestOutputHelper output) : IAsyncLifetime
{
    private const string ClientId = "crash-gateway";
    private const int Changes = 30;
    private readonly string _state = MqttGatewayConfig.NewStateDirectory();
    private readonly List<GatewayProcess> _gateways = new();
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private VirtualPlc _plc = null!;
    private TestSubscriber _subscriber = null!;

    private static string Counter => MqttGatewayConfig.Topic("counter");

    private static string Lost => $"{MqttGatewayConfig.Prefix}/status/{ClientId}/lost";

    public async Task InitializeAsync()
    {
        _broker = await MosquittoBroker.StartAsync();
        _plc = new VirtualPlc();
        _simulator = await RecordingSimulator.StartAsync(_plc);

        // A persistent session: the broker keeps the subscription, and what arrives for it, across its restart.
        _subscriber = await TestSubscriber.ConnectAsync(_broker, [Counter, Lost], clientId: "crash-subscriber", persistentSession: true);
    }

    public async Task DisposeAsync()
    {
        foreach (GatewayProcess gateway in _gateways)
        {
            output.WriteLine($"gateway {gateway.Id}:{Environment.NewLine}{gateway.Output}");
            await gateway.DisposeAsync();
        }

        output.WriteLine("messages:" + Environment.NewLine + _subscriber.Dump());
        await _subscriber.DisposeAsync();
        await _simulator.DisposeAsync();
        output.WriteLine("mosquitto:" + Environment.NewLine + _broker.Log);
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task With_the_durable_queue_every_change_queued_before_a_SIGKILL_arrives_once_in_order_after_restart()
    {
        GatewayProcess first = await StartGatewayAsync(durable: true);
        await _subscriber.WaitUntilAsync(ms => Values(ms).Contains(0), "the first value");

        await OutageThenKillAsync(first);
        GatewayProcess second = await StartGatewayAsync(durable: true);
        (await second.WaitForOutputAsync($"{Changes} message(s) from the previous run are sent first", TimeSpan.FromSeconds(30))).Should().BeTrue(second.Output);
        await _broker.RestartAsync();

        // The changes of the outage, then the new run's first reading of the same value (a message of its own).
        await _subscriber.WaitUntilAsync(ms => Values(ms).Count(v => v == Changes) == 2, "every change and the new run's first value", TimeSpan.FromSeconds(60));
        IReadOnlyList<ReceivedMessage> received = Delivered(_subscriber.Messages);
        Values(received).Should().Equal([0, .. Enumerable.Range(1, Changes), Changes], "each change once, in order");
        received.Select(m => m.Payload).Should().OnlyHaveUniqueItems("no message is delivered twice");
        _subscriber.Messages.Should().NotContain(m => m.Topic == Lost, "nothing was lost");
    }

    [Fact]
    public async Task Without_the_durable_queue_the_restarted_gateway_announces_how_many_changes_it_may_have_lost()
    {
        GatewayProcess first = await StartGatewayAsync(durable: false);
        await _subscriber.WaitUntilAsync(ms => Values(ms).Contains(0), "the first value");

        await OutageThenKillAsync(first);
        GatewayProcess second = await StartGatewayAsync(durable: false);
        (await second.WaitForOutputAsync($"the previous run ended with {Changes} message(s) the broker had not acknowledged", TimeSpan.FromSeconds(30))).Should().BeTrue(second.Output);
        await _broker.RestartAsync();

        ReceivedMessage announcement = await _subscriber.WaitForAsync(Lost, patience: TimeSpan.FromSeconds(60));
        using (JsonDocument lost = JsonDocument.Parse(announcement.Payload))
        {
            lost.RootElement.GetProperty("lost").GetInt64().Should().Be(Changes, "the changes queued when the gateway was killed");
        }

        await _subscriber.WaitUntilAsync(ms => Values(ms).Contains(Changes), "the new run's first value", TimeSpan.FromSeconds(30));
        Values(Delivered(_subscriber.Messages)).Should().Equal([0, Changes], "the changes of the outage are gone with the first process");
        _subscriber.Messages.Count(m => m.Topic == Lost).Should().Be(1);
    }

    /// <summary>The broker stops, the PLC's counter runs 1..Changes (each read by the gateway), then the gateway is killed.</summary>
    private async Task OutageThenKillAsync(GatewayProcess gateway)
    {
        await _broker.StopAsync();
        for (int k = 1; k <= Changes; k++)
        {
            // The next value only once the gateway has read this one (it logs each change): a read retried on a loaded
            // machine must not skip a value.
            _plc.WriteWords("D0", [(ushort)k]);
            string read = $"plc/counter: unit 0 D0 = {k}";
            (await gateway.WaitForLineAsync(l => l.EndsWith(read, StringComparison.Ordinal), TimeSpan.FromSeconds(30))).Should().NotBeNull(gateway.Output);
        }

        await _simulator.WaitForAnswersAsync(_simulator.Answers, 3); // the last change is queued: reads go on past it
        await gateway.KillAsync();
    }

    private async Task<GatewayProcess> StartGatewayAsync(bool durable)
    {
        GatewayProcess gateway = GatewayProcess.Start(
        [
            $"--HostLink:Links:plc:Tcp=127.0.0.1:{_simulator.Port}",
            "--HostLink:Links:plc:TurnaroundAllowance=200ms",
            "--HostLink:Links:plc:Groups:counter:Address=D0",
            "--HostLink:Links:plc:Groups:counter:Type=uint16",
            "--HostLink:Links:plc:Groups:counter:Interval=20ms",
            "--HostLink:Links:plc:Groups:counter:Log=OnChange",
            "--Mqtt:Host=127.0.0.1",
            $"--Mqtt:Port={_broker.Port}",
            $"--Mqtt:ClientId={ClientId}",
            $"--Mqtt:TopicPrefix={MqttGatewayConfig.Prefix}",
            "--Mqtt:Reconnect:Initial=100ms",
            "--Mqtt:Reconnect:Max=500ms",
            $"--Mqtt:StateDirectory={_state}",
            $"--Mqtt:DurableQueue:Enabled={(durable ? "true" : "false")}",
            "--Logging:LogLevel:Default=Information",
        ]);
        _gateways.Add(gateway);
        (await gateway.WaitForOutputAsync("link plc: polling", TimeSpan.FromSeconds(60))).Should().BeTrue(gateway.Output);
        return gateway;
    }

    /// <summary>
    /// The counter's messages as the gateway delivered them. The broker keeps the retained value (across its restart too)
    /// and hands it to a subscriber that subscribes, even as the same message reaches it live: two copies of one message,
    /// one of them flagged retained, are the broker's doing, not a second delivery by the gateway. So is a copy flagged
    /// DUP: the persistent session's message whose acknowledgement the stopping broker did not take, sent again when the
    /// session resumes (QoS 1 is at least once between the broker and a subscriber).
    /// </summary>
    private static ReceivedMessage[] Delivered(IEnumerable<ReceivedMessage> messages)
    {
        ReceivedMessage[] all = messages.Where(m => m.Topic == Counter).ToArray();
        return all.Where((m, i) => !all.Take(i).Any(p => p.Payload == m.Payload && (p.Retain || m.Retain || m.Duplicate))).ToArray();
    }

    private static List<int> Values(IEnumerable<ReceivedMessage> messages)
        => messages.Where(m => m.Topic == Counter).Select(m =>
        {
            using JsonDocument d = JsonDocument.Parse(m.Payload);
            return d.RootElement.GetProperty("value").GetInt32();
        }).ToList();
}
