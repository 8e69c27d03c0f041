using System.Text.Json;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Polling;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// Write commands that try to turn the gateway against the plant or against its own topics: replies redirected,
/// retained commands, ambiguous JSON, numbers the tag cannot hold. Each is refused, and the PLC's memory shows it.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttWriteSafetyTests(ITestOutputHelper output) : IAsyncLifetime
{
    private const string ClientId = "gateway-safety";
    private readonly List<IAsyncDisposable> _cleanup = new();
    private readonly CapturingLoggerProvider _logs = new();
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private TestSubscriber _client = null!;
    private VirtualPlc _plc = null!;

    private static string Setpoint => MqttGatewayConfig.Topic("setpoint");

    private static string Temperature => MqttGatewayConfig.Topic("temperature");

    public async Task InitializeAsync()
    {
        _broker = await MosquittoBroker.StartAsync();
        _plc = new VirtualPlc();
        _plc.WriteWords("D500", [100]);
        _plc.WriteWords("D700", [0x0000, 0x41AC]); // 21.5
        _simulator = await RecordingSimulator.StartAsync(_plc);
        _client = await TestSubscriber.ConnectAsync(_broker, ["#"]);
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
        output.WriteLine("messages:" + Environment.NewLine + _client.Dump());
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task A_reply_to_a_status_value_or_foreign_topic_is_refused_and_answered_on_the_commands_own_result_topic()
    {
        await StartGateway();
        string status = $"{MqttGatewayConfig.Prefix}/status/{ClientId}";
        string value = MqttGatewayConfig.Topic("readonly");
        await _client.WaitForAsync(status, m => m.Payload == "online");
        await _client.WaitForAsync(value);
        int before = _client.Messages.Count;

        await _client.PublishAsync(Setpoint + "/set", "-8", responseTopic: status);
        await _client.PublishAsync(Setpoint + "/set", "-8", responseTopic: value);
        await _client.PublishAsync(Setpoint + "/set", "-8", responseTopic: "elsewhere/outside/the/prefix");
        await _client.PublishAsync(Setpoint + "/set", "-8", responseTopic: "repliesX/a"); // shares the prefix's letters only

        await _client.WaitUntilAsync(ms => ms.Count(m => m.Topic == Setpoint + "/set/result") == 4, "four replies on the command's own result topic");
        string[] replies = _client.PayloadsOn(Setpoint + "/set/result").ToArray();
        replies.Should().OnlyContain(r => r.Contains("\"status\":\"refused\"", StringComparison.Ordinal) && r.Contains("Mqtt:Writes:ReplyPrefixes", StringComparison.Ordinal));
        IReadOnlyList<ReceivedMessage> after = _client.Messages.Skip(before).ToArray();
        after.Should().NotContain(m => m.Topic == status && m.Payload != "online", "nothing but the gateway's state reaches its status topic");
        after.Should().NotContain(m => m.Topic == value && m.Payload.Contains("status", StringComparison.Ordinal), "no reply lands on a value topic");
        after.Should().NotContain(m => m.Topic.StartsWith("elsewhere/", StringComparison.Ordinal) || m.Topic.StartsWith("repliesX/", StringComparison.Ordinal));
        _logs.WithEvent(MqttLog.Events.WriteRefused).Should().HaveCount(4);
        _simulator.Received.Select(RecordingSimulator.Header).Should().OnlyContain(h => h.StartsWith('R'), "only reads reach the PLC");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);

        // Under the configured prefix, and on the result topic named explicitly, a reply goes where it was asked to.
        await _client.PublishAsync(Setpoint + "/set", "5", responseTopic: "replies/scada/7");
        (await _client.WaitForAsync("replies/scada/7")).Payload.Should().Contain("\"status\":\"done\"");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)5]);
    }

    [Fact]
    public async Task A_retained_command_is_never_executed_live_or_stored_and_clearing_it_is_ignored_quietly()
    {
        // Stored: published retained before the gateway subscribes.
        await _client.PublishAsync(Setpoint + "/set", "777", retain: true);
        await StartGateway();
        await _client.WaitForAsync(Setpoint);

        // Live: published retained while the gateway is subscribed.
        await _client.PublishAsync(Setpoint + "/set", "778", retain: true);
        ReceivedMessage refused = await _client.WaitForAsync(Setpoint + "/set/result");
        refused.Payload.Should().Contain("\"status\":\"refused\"").And.Contain("retain flag");

        // Cleared: an empty retained message on the command topic.
        await _client.PublishAsync(Setpoint + "/set", "", retain: true);
        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.RetainedCommandCleared).Count == 1, "the clearing is seen", _logs);

        _simulator.Received.Select(RecordingSimulator.Header).Should().NotContain("WD", "no retained command reaches the PLC");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);

        // A plain command afterwards is carried out: the ones before were refused, not queued.
        await _client.PublishAsync(Setpoint + "/set", "9");
        await _client.WaitUntilAsync(ms => ms.Count(m => m.Topic == Setpoint + "/set/result") == 2, "the plain command's reply");
        _client.PayloadsOn(Setpoint + "/set/result").Should().HaveCount(2, "the stored command and the clearing get no reply");
        _client.PayloadsOn(Setpoint + "/set/result")[1].Should().Contain("\"status\":\"done\"");
        _simulator.Received.Select(RecordingSimulator.Header).Count(h => h == "WD").Should().Be(1, "only the plain command was written");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)9]);
    }

    public static TheoryData<string, string, string> Unstorable => new()
    {
        // tag, payload, what the refusal says
        { "setpoint", """{"value":12,"value":600}""", "Duplicate" },
        { "setpoint", """{"value":12,"Value":600}""", "takes \"value\" only" },
        { "setpoint", """{"value":12,"comment":"x"}""", "takes \"value\" only" },
        { "setpoint", "40000", "int16 takes a whole number from -32768 to 32767" },
        { "setpoint", "1e2", "int16 takes a whole number" },
        { "temperature", "1e-50", "a float takes a JSON number" },
        { "temperature", "-1e-40", "a float takes a JSON number" },
        { "temperature", "1e-400", "a float takes a JSON number" },
        { "temperature", "3.5e38", "a float takes a JSON number" },
        { "temperature", "1e400", "a float takes a JSON number" },
        { "temperature", "\"NaN\"", "a float takes a JSON number" },
        { "temperature", "NaN", "not JSON" },
    };

    [Theory]
    [MemberData(nameof(Unstorable))]
    public async Task Ambiguous_json_and_numbers_the_tag_cannot_hold_are_refused_and_memory_is_unchanged(string tag, string payload, string reason)
    {
        await StartGateway();
        string topic = MqttGatewayConfig.Topic(tag);

        await _client.PublishAsync(topic + "/set", payload);

        ReceivedMessage reply = await _client.WaitForAsync(topic + "/set/result");
        using (JsonDocument result = JsonDocument.Parse(reply.Payload))
        {
            result.RootElement.GetProperty("status").GetString().Should().Be("refused");
            result.RootElement.GetProperty("error").GetString().Should().Contain(reason);
        }

        reply.Payload.Should().NotContain("\\u0022").And.NotContain("\\u0027", "a reply escapes only what JSON requires");
        _simulator.Received.Select(RecordingSimulator.Header).Where(h => !h.StartsWith('R')).Should().BeEmpty("only reads reach the PLC (the refusal may come before the first)");
        _plc.ReadWords("D500", 1).Should().Equal([(ushort)100]);
        _plc.ReadWords("D700", 2).Should().Equal([(ushort)0x0000, (ushort)0x41AC]);
    }

    [Theory]
    [InlineData("0", (ushort)0x0000, (ushort)0x0000)]
    [InlineData("-0.0", (ushort)0x0000, (ushort)0x8000)]
    [InlineData("1.17549435e-38", (ushort)0x0000, (ushort)0x0080)]
    [InlineData("3.4028235e38", (ushort)0xFFFF, (ushort)0x7F7F)]
    public async Task Zero_and_the_ends_of_the_float_range_are_written(string payload, ushort low, ushort high)
    {
        await StartGateway();

        await _client.PublishAsync(Temperature + "/set", payload);

        (await _client.WaitForAsync(Temperature + "/set/result")).Payload.Should().Contain("\"status\":\"done\"");
        _plc.ReadWords("D700", 2).Should().Equal([low, high], "IEEE 754 single, low word first");
    }

    private async Task StartGateway()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(_simulator.Port, _broker, ClientId);
        config["Mqtt:Writes:Enabled"] = "true";
        config["Mqtt:Writes:ReplyPrefixes:0"] = "replies";

        // The frames' headers tell reads (R…) from writes: the link reads by area, without MM and QQ.
        config["HostLink:Links:plc:UseCompoundRead"] = "Off";
        MqttGatewayConfig.Group(config, "setpoint", "D500", "int16", intervalMs: 50, writable: true);
        MqttGatewayConfig.Group(config, "temperature", "D700", "float", intervalMs: 50, writable: true);
        MqttGatewayConfig.Group(config, "readonly", "D600", "int16", intervalMs: 50);
        IHost host = MqttGatewayConfig.Build(config, _logs);
        _cleanup.Add(new AsyncHost(host));
        await host.StartAsync();
        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(MqttLog.Events.WritesAccepted).Count > 0, "the gateway subscribes to its command topics", _logs);

        // A command that comes before the link is set up is refused ("not being polled"): wait for the link.
        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(GatewayLog.Events.LinkStarted).Count > 0, "the link polls", _logs);
    }

}
