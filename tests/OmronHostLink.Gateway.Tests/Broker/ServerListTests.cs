using System.Diagnostics;
using System.Diagnostics.Metrics;
using System.Globalization;
using System.Text.Json;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Diagnostics.Metrics.Testing;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Sparkplug;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Broker;

/// <summary>
/// Two Mosquitto brokers as an ordered server list for both outputs: a stopped broker sends them to the next one, a
/// primary host application offline on its broker sends the Sparkplug node to the next one, and the brokers' shared log
/// shows each client connected to one broker at a time.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class ServerListTests(ITestOutputHelper output) : IAsyncLifetime
{
    private const string ClientId = "worker-test";
    private const string NodeClientId = SparkplugEndToEndTests.Group + "-" + SparkplugEndToEndTests.Node;
    private static readonly TimeSpan KeepAlive = TimeSpan.FromSeconds(5);

    private readonly string _logFile = Path.Combine(Directory.CreateTempSubdirectory("ohl-brokers-").FullName, "shared.log");
    private readonly CapturingLoggerProvider _logs = new();
    private readonly VirtualPlc _plc = new();
    private MosquittoBroker _first = null!;
    private MosquittoBroker _second = null!;
    private RecordingSimulator _simulator = null!;
    private IHost? _host;
    private readonly List<TestSubscriber> _subscribers = [];

    public async Task InitializeAsync()
    {
        _plc.WriteWords("D100", [5]);
        _first = await MosquittoBroker.StartAsync(new MosquittoSettings { SharedLogFile = _logFile, LogTag = "A" });
        _second = await MosquittoBroker.StartAsync(new MosquittoSettings { SharedLogFile = _logFile, LogTag = "B" });
        _simulator = await RecordingSimulator.StartAsync(_plc);
    }

    public async Task DisposeAsync()
    {
        if (_host is not null)
        {
            await _host.StopAsync();
            _host.Dispose();
        }

        output.WriteLine(_logs.Dump());
        foreach (TestSubscriber subscriber in _subscribers)
        {
            await subscriber.DisposeAsync();
        }

        await _simulator.DisposeAsync();
        output.WriteLine("brokers:" + Environment.NewLine + (File.Exists(_logFile) ? File.ReadAllText(_logFile) : "(no log)"));
        await _first.DisposeAsync();
        await _second.DisposeAsync();
    }

    [Fact]
    public async Task Stopping_the_first_broker_moves_both_outputs_to_the_second_within_two_keep_alives_one_connection_at_a_time()
    {
        Dictionary<string, string?> config = Config(json: true);
        TestSubscriber onFirst = await Subscriber(_first);
        TestSubscriber onSecond = await Subscriber(_second);
        _host = MqttGatewayConfig.Build(config, _logs);
        await _host.StartAsync();
        await onFirst.WaitUntilAsync(ms => ms.Any(m => m.Topic == MqttGatewayConfig.Topic("level")) && SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NBirth), "both outputs publish on the first broker");
        onSecond.Messages.Should().BeEmpty("nothing goes to the second while the first is there");
        BrokerConnections connections = _host.Services.GetRequiredService<BrokerConnections>();
        connections.Statuses().Select(s => (s.Output, s.Server, s.State)).Should().Equal(("mqtt", Address(_first), BrokerState.Connected), ("sparkplug", Address(_first), BrokerState.Connected));

        var moving = Stopwatch.StartNew();
        await _first.StopAsync();

        await onSecond.WaitUntilAsync(
            ms => ms.Any(m => m.Topic == MqttGatewayConfig.Topic("level")) && SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NBirth),
            "both outputs publish on the second broker",
            KeepAlive * 4);
        TimeSpan moved = moving.Elapsed;
        output.WriteLine($"both outputs on the second broker {moved.TotalMilliseconds:0} ms after the first was stopped");
        moved.Should().BeLessThan(KeepAlive * 2);
        await MqttGatewayConfig.Eventually(() => connections.Statuses().All(s => s.Server == Address(_second) && s.State == BrokerState.Connected), "both connections report the second server", _logs);
        connections.Statuses().Select(s => (s.ServerKey, s.ServerNumber)).Should().Equal(("Mqtt:Servers:1", 2), ("Sparkplug:Servers:1", 2));

        // The server in use: logged, and in the gauge.
        _logs.WithEvent(BrokerLog.Events.ServerInUse).Select(e => e.Message).Should().Contain(m => m.StartsWith("MQTT: using " + Address(_second), StringComparison.Ordinal))
            .And.Contain(m => m.StartsWith("Sparkplug: using " + Address(_second), StringComparison.Ordinal));
        using (var gauge = new MetricCollector<int>(_host.Services.GetRequiredService<IMeterFactory>(), GatewayNames.Meter, BrokerConnections.ServerGaugeName))
        {
            gauge.RecordObservableInstruments();
            gauge.GetMeasurementSnapshot().Where(m => m.Value == 1).Select(m => ((string)m.Tags["hostlink.output"]!, (int)m.Tags["server.port"]!))
                .Should().BeEquivalentTo([("mqtt", _second.Port), ("sparkplug", _second.Port)]);
        }

        // The statistics say which server each output uses, and the node's births: a snapshot taken as the node
        // connected may come before its births there, the next one (every second) follows them.
        string outputsTopic = $"{MqttGatewayConfig.Prefix}/status/{ClientId}/outputs";
        ReceivedMessage statistics = await onSecond.WaitForAsync(
            outputsTopic,
            m => m.Payload.Split($"\"state\":\"connected\",\"server\":\"{Address(_second)}\"").Length == 3 && SparkplugBirths(m.Payload) >= 4);
        using (JsonDocument document = JsonDocument.Parse(statistics.Payload))
        {
            JsonElement[] outputs = document.RootElement.GetProperty("outputs").EnumerateArray().ToArray();
            outputs.Select(o => (o.GetProperty("output").GetString(), o.GetProperty("serverKey").GetString(), o.GetProperty("serverNumber").GetInt32())).Should().Equal(("mqtt", "Mqtt:Servers:1", 2), ("sparkplug", "Sparkplug:Servers:1", 2));
            outputs[1].GetProperty("figures").GetProperty("births").GetInt64().Should().BeGreaterThanOrEqualTo(4, "NBIRTH and DBIRTH on each broker");
            outputs[1].GetProperty("figures").GetProperty("rebirthsRequested").GetInt64().Should().Be(0);
            outputs[0].GetProperty("connections").GetInt64().Should().Be(2);
        }

        // Polling goes on, and its changes reach the second broker.
        _plc.WriteWords("D100", [42]);
        await onSecond.WaitForAsync(MqttGatewayConfig.Topic("level"), m => m.Payload.Contains("\"value\":42", StringComparison.Ordinal));

        AssertOneConnectionAtATime(ClientId, ["A", "B"]);
        AssertOneConnectionAtATime(NodeClientId, ["A", "B"]);
    }

    [Fact]
    public async Task A_primary_host_offline_on_the_first_broker_makes_the_node_walk_to_the_second_and_be_born_there()
    {
        const string hostId = "scada";
        Dictionary<string, string?> config = Config(json: false);
        config["Sparkplug:PrimaryHostId"] = hostId;
        TestSubscriber onFirst = await Subscriber(_first);
        TestSubscriber onSecond = await Subscriber(_second);
        string online = State(true, 1_700_000_000_000);
        await onFirst.PublishAsync("spBv1.0/STATE/" + hostId, online, retain: true);
        await onSecond.PublishAsync("spBv1.0/STATE/" + hostId, online, retain: true);
        _host = MqttGatewayConfig.Build(config, _logs);
        await _host.StartAsync();
        await onFirst.WaitUntilAsync(ms => SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NBirth), "the node is born on the first broker");

        // The primary host lost its session on the first broker: its will.
        await onFirst.PublishAsync("spBv1.0/STATE/" + hostId, State(false, 1_700_000_000_000), retain: true);

        await onFirst.WaitUntilAsync(ms => SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NDeath), "NDEATH on the first broker");
        await onSecond.WaitUntilAsync(ms => SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.NBirth), "the node is born on the second broker");
        using var tahu = new TahuCodec();
        async Task<string> BdSeq(TestSubscriber s, string topic) => (string)SparkplugEndToEndTests.Metric(await tahu.DecodeAsync(s.Messages.First(m => m.Topic == topic).Bytes!), "bdSeq")["value"]!;
        (await BdSeq(onFirst, SparkplugEndToEndTests.NBirth)).Should().Be("0");
        (await BdSeq(onFirst, SparkplugEndToEndTests.NDeath)).Should().Be("0", "the death ends the first session");
        (await BdSeq(onSecond, SparkplugEndToEndTests.NBirth)).Should().Be("1", "a new connection, a new bdSeq");
        _logs.WithEvent(1312).Should().ContainSingle().Which.Message.Should().Contain("primary host application scada is offline").And.Contain("trying " + Address(_second) + " (Sparkplug:Servers:1) at once");
        _logs.WithEvent(BrokerLog.Events.ServerInUse).Select(e => e.Message).Should().Contain(m => m.StartsWith("Sparkplug: using " + Address(_second), StringComparison.Ordinal));
        onFirst.Messages.Count(m => m.Topic == SparkplugEndToEndTests.NBirth).Should().Be(1, "the node left the first broker");

        AssertOneConnectionAtATime(NodeClientId, ["A", "B"]);
    }

    private void AssertOneConnectionAtATime(string clientId, string[] expected)
    {
        (IReadOnlyList<string> connections, IReadOnlyList<string> overlaps) = ConnectionTimeline.Read(_logFile, clientId);
        connections.Should().Equal(expected, "{0} connects to the first broker, then to the second", clientId);
        overlaps.Should().BeEmpty("{0} is never connected to two brokers at once", clientId);
    }

    private static string Address(MosquittoBroker broker) => $"127.0.0.1:{broker.Port}";

    private static string State(bool online, long timestamp) => $"{{\"online\":{(online ? "true" : "false")},\"timestamp\":{timestamp}}}";

    private async Task<TestSubscriber> Subscriber(MosquittoBroker broker)
    {
        TestSubscriber subscriber = await TestSubscriber.ConnectAsync(broker, [MqttGatewayConfig.Prefix + "/#", SparkplugEndToEndTests.Namespace + "/#"]);
        _subscribers.Add(subscriber);
        return subscriber;
    }

    /// <summary>Sparkplug (and the JSON output with <paramref name="json"/>) on the list of both brokers, the first one first.</summary>
    private Dictionary<string, string?> Config(bool json)
    {
        Dictionary<string, string?> config = SparkplugEndToEndTests.Config(_simulator.Port, _first);
        config.Remove("Sparkplug:Host");
        config.Remove("Sparkplug:Port");
        Servers(config, "Sparkplug");
        config["Sparkplug:KeepAlive"] = KeepAlive.ToString();
        if (json)
        {
            foreach ((string key, string? value) in MqttGatewayConfig.Create(_simulator.Port, _first, ClientId).Where(k => k.Key.StartsWith("Mqtt:", StringComparison.Ordinal)))
            {
                config[key] = value;
            }

            config.Remove("Mqtt:Host");
            config.Remove("Mqtt:Port");
            Servers(config, "Mqtt");
            config["Mqtt:KeepAlive"] = KeepAlive.ToString();
            config["Mqtt:StatisticsInterval"] = "1s";
        }

        MqttGatewayConfig.Group(config, "level", "D100");
        return config;
    }

    private void Servers(Dictionary<string, string?> config, string section)
    {
        config[$"{section}:Servers:0:Host"] = "127.0.0.1";
        config[$"{section}:Servers:0:Port"] = _first.Port.ToString(CultureInfo.InvariantCulture);
        config[$"{section}:Servers:1:Host"] = "127.0.0.1";
        config[$"{section}:Servers:1:Port"] = _second.Port.ToString(CultureInfo.InvariantCulture);
    }

    private static long SparkplugBirths(string outputs)
    {
        using JsonDocument document = JsonDocument.Parse(outputs);
        return document.RootElement.GetProperty("outputs").EnumerateArray()
            .Where(o => o.GetProperty("output").GetString() == "sparkplug")
            .Select(o => o.GetProperty("figures").GetProperty("births").GetInt64())
            .FirstOrDefault();
    }
}
