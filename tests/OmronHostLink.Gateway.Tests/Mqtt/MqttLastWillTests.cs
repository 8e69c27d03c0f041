using OmronHostLink.Gateway.Tests.Telemetry;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>The worker as a separate process, killed outright: the broker publishes its last will.</summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttLastWillTests(ITestOutputHelper output)
{
    [Fact]
    public async Task A_killed_worker_is_reported_offline_by_its_last_will()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [5]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        string status = $"{MqttGatewayConfig.Prefix}/status/worker-kill";
        await using TestSubscriber subscriber = await TestSubscriber.ConnectAsync(broker, [status, MqttGatewayConfig.Topic("level")]);

        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker, clientId: "worker-kill");
        MqttGatewayConfig.Group(config, "level", "D100", intervalMs: 50);
        await using GatewayProcess worker = GatewayProcess.Start(config.Select(c => $"--{c.Key}={c.Value}"));
        try
        {
            await subscriber.WaitUntilAsync(ms => ms.Any(m => m.Topic == status && m.Payload == "online") && ms.Any(m => m.Topic == MqttGatewayConfig.Topic("level")), "the worker process is online and publishing");

            await worker.KillAsync(); // SIGKILL: no clean disconnect, no "offline" of its own

            await subscriber.WaitUntilAsync(ms => ms.Any(m => m.Topic == status && m.Payload == "offline"), "the broker publishes the last will");
            subscriber.PayloadsOn(status).Should().Equal("online", "offline");
            await using TestSubscriber late = await TestSubscriber.ConnectAsync(broker, [status]);
            ReceivedMessage retained = await late.WaitForAsync(status);
            retained.Payload.Should().Be("offline", "the last will is retained");
            retained.Retain.Should().BeTrue();
        }
        finally
        {
            output.WriteLine("worker process:" + Environment.NewLine + worker.Output);
            output.WriteLine("mosquitto:" + Environment.NewLine + broker.Log);
        }
    }
}
