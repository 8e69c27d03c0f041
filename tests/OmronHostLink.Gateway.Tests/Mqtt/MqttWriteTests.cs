using System.Text;
using System.Text.Json;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>Write commands over MQTT: allowlisted tags reach PLC memory; anything else never reaches the wire.</summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttWriteTests(ITestOutputHelper output) : IAsyncLifetime
{
    private readonly List<IAsyncDisposable> _cleanup = new();
    private readonly CapturingLoggerProvider _logs = new();
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private TestSubscriber _client = null!;
    private VirtualPlc _plc = null!;

    public async Task InitializeAsync()
    {
        _broker = await MosquittoBroker.StartAsync();
        _plc = new VirtualPlc();
        _plc.WriteWords("D500", [100]);
        _plc.WriteWords("D600", [200]);
        _simulator = await RecordingSimulator.StartAsync(_plc);
        _client = await TestSubscriber.ConnectAsync(_broker, [$"{MqttGatewayConfig.Prefix}/#", "replies/#"]);
    }

    public async Task DisposeAsync()
    {
        foreach (IAsyncDisposable d in Enumerable.Reverse(_cleanup))
        {
            await d.DisposeAsync();
        }

        await _client.DisposeAsync();
        await _simulator.DisposeAsync();
        output.WriteLine(_logs.Dump());
        output.WriteLine("mosquitto:" + Environment.NewLine + _broker.Log);
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task An_allowlisted_write_round_trips_to_plc_memory_and_replies_on_the_response_topic()
    {
        await StartWorker(writes: true);
        string setpoint = MqttGatewayConfig.Topic("setpoint");

        byte[] correlation = Encoding.UTF8.GetBytes("request-17");
        await _client.PublishAsync(setpoint + "/set", "1234", responseTopic: "replies/scada", correlationData: correlation);

        ReceivedMessage reply = await _client.WaitForAsync("replies/scada");
        reply.CorrelationData.Should().Equal(correlation);
        using (JsonDocument result = JsonDocument.Parse(reply.Payload))
        {
            result.RootElement.GetProperty("status").GetString().Should().Be("done");
            result.RootElement.GetProperty("tag").GetString().Should().Be(setpoint);
        }

        _plc.ReadWords("D500", 1).Should().Equal([(ushort)1234]);
        _simulator.Received.Select(RecordingSimulator.Header).Should().Contain("WD", "the write went out as C-mode WD");
        await _client.WaitUntilAsync(ms => ms.Any(m => m.Topic == setpoint && m.Payload.Contains("\"value\":1234", StringComparison.Ordinal)), "the next poll publishes the written value");

        // Without a response topic the reply goes to …/set/result; {"value": …} is accepted too.
        await _client.PublishAsync(setpoint + "/set", """{"value": -5}""");
        ReceivedMessage plain = await _client.WaitForAsync(setpoint + "/set/result");
        plain.Payload.Should().Contain("\"status\":\"done\"");
        _plc.ReadWords("D500", 1).Should().Equal([unchecked((ushort)-5)]);
    }

    [Fact]
    public async Task A_write_to_a_tag_not_allowlisted_never_reaches_the_plc()
    {
        await StartWorker(writes: true);
        string readOnly = MqttGatewayConfig.Topic("readonly");
        long answers = _simulator.Answers;

        await _client.PublishAsync(readOnly + "/set", "999");
        await _client.PublishAsync(MqttGatewayConfig.Topic("nosuchtag") + "/set", "999");
        await _client.PublishAsync(MqttGatewayConfig.Topic("setpoint") + "/set", "70000"); // writable, but not an int16
        await _client.PublishAsync(MqttGatewayConfig.Topic("setpoint") + "/set", "not json");

        await _client.WaitUntilAsync(ms => ms.Count(m => m.Topic.EndsWith("/set/result", StringComparison.Ordinal)) == 4, "four replies");
        string[] replies = _client.Messages.Where(m => m.Topic.EndsWith("/set/result", StringComparison.Ordinal)).Select(m => m.Payload).ToArray();
        replies.Should().OnlyContain(r => r.Contains("\"status\":\"refused\"", StringComparison.Ordinal));
        replies[0].Should().Contain("not writable");
        replies[1].Should().Contain("no tag nosuchtag");
        replies[2].Should().Contain("int16 takes a whole number from -32768 to 32767; got 70000");
        replies[3].Should().Contain("not JSON");
        _logs.WithEvent(MqttLog.Events.WriteRefused).Should().HaveCount(4);

        // More polls go by; the PLC has seen reads only, and its memory is as it was.
        await _simulator.WaitForAnswersAsync(answers, 10);
        _simulator.Received.Select(RecordingSimulator.Header).Should().OnlyContain(h => h.StartsWith('R'), "only reads (RD, RR) reach the PLC");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);
        _plc.ReadWords("D600", 1).Should().Equal([(ushort)200]);
    }

    [Fact]
    public async Task With_writes_disabled_the_worker_takes_no_command_even_for_a_writable_tag()
    {
        await StartWorker(writes: false);
        await _client.WaitUntilAsync(ms => ms.Any(m => m.Topic == MqttGatewayConfig.Topic("setpoint")), "the worker publishes");

        await _client.PublishAsync(MqttGatewayConfig.Topic("setpoint") + "/set", "1234");
        long answers = _simulator.Answers;
        await _simulator.WaitForAnswersAsync(answers, 20);

        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);
        _simulator.Received.Select(RecordingSimulator.Header).Should().OnlyContain(h => h.StartsWith('R'));
        _client.Messages.Should().NotContain(m => m.Topic.EndsWith("/result", StringComparison.Ordinal), "the worker does not even subscribe");
    }

    [Fact]
    public async Task A_write_the_plc_refuses_replies_failed_with_its_end_code()
    {
        _plc.Mode = PlcMode.Run; // writes to DM are refused in RUN mode, as on a real PLC
        await StartWorker(writes: true);
        string setpoint = MqttGatewayConfig.Topic("setpoint");

        await _client.PublishAsync(setpoint + "/set", "1234");

        ReceivedMessage reply = await _client.WaitForAsync(setpoint + "/set/result");
        using JsonDocument result = JsonDocument.Parse(reply.Payload);
        result.RootElement.GetProperty("status").GetString().Should().Be("failed");
        result.RootElement.GetProperty("endCode").GetString().Should().Be("01");
        result.RootElement.GetProperty("error").GetString().Should().NotBeNullOrEmpty();
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);
        _logs.WithEvent(MqttLog.Events.WriteFailed).Should().ContainSingle();
    }

    [Fact]
    public async Task A_writable_bit_is_set_through_the_same_link()
    {
        await StartWorker(writes: true);
        string valve = MqttGatewayConfig.Topic("valve");

        await _client.PublishAsync(valve + "/set", "true");

        ReceivedMessage reply = await _client.WaitForAsync(valve + "/set/result");
        reply.Payload.Should().Contain("\"status\":\"done\"");
        _plc.GetBit("CIO10.03").Should().BeTrue();
        _plc.GetBit("CIO10.02").Should().BeFalse();
        _simulator.Received.Select(RecordingSimulator.Header).Should().Contain("FA", "a bit is written with FINS MEMORY AREA WRITE");
        await _client.WaitUntilAsync(ms => ms.Any(m => m.Topic == valve && m.Payload.Contains("\"value\":true", StringComparison.Ordinal)), "the bit reads back");
    }

    private async Task StartWorker(bool writes)
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(_simulator.Port, _broker);
        config["Mqtt:Writes:Enabled"] = writes ? "true" : "false";

        // The frames' headers tell reads (R…) from writes: the link reads by area, without MM and QQ.
        config["HostLink:Links:plc:UseCompoundRead"] = "Off";
        config["Mqtt:Writes:ReplyPrefixes:0"] = "replies";
        MqttGatewayConfig.Group(config, "setpoint", "D500", "int16", intervalMs: 50, writable: true);
        MqttGatewayConfig.Group(config, "readonly", "D600", "int16", intervalMs: 50);
        MqttGatewayConfig.Group(config, "valve", "CIO10.03", "bit", intervalMs: 50, writable: true);
        IHost host = MqttGatewayConfig.Build(config, _logs);
        _cleanup.Add(new AsyncHost(host));
        await host.StartAsync();
        if (writes)
        {
            // Commands are taken once the worker has subscribed.
            await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.WritesAccepted).Count > 0, "the worker subscribes to its command topics", _logs);

            // A command that comes before the link is set up is refused ("not being polled"): wait for the link.
            await MqttGatewayConfig.Eventually(() => _logs.WithEvent(GatewayLog.Events.LinkStarted).Count > 0, "the link polls", _logs);
        }
    }

}
