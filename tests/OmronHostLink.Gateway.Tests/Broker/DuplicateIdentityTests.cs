using System.Diagnostics;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Sparkplug;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Broker;

/// <summary>
/// Two gateways started with the same client id (a copied configuration): the broker hands the session to whichever
/// connected last. Each gateway says so once, as an error naming the id and the broker, and reconnects no faster than
/// its backoff (Reconnect:Initial doubling to Reconnect:Max, not reset by such short sessions) — over MQTT 5 (JSON) the
/// broker says the session was taken over; over MQTT 3.1.1 (Sparkplug) it only closes the connection, twice in a row
/// just after accepting it. The Sparkplug births follow the connections, no more.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class DuplicateIdentityTests(ITestOutputHelper output) : IAsyncLifetime
{
    private static readonly TimeSpan Initial = TimeSpan.FromMilliseconds(250);
    private static readonly TimeSpan Max = TimeSpan.FromSeconds(2);
    private readonly string _logFile = Path.Combine(Directory.CreateTempSubdirectory("ohl-duplicate-").FullName, "broker.log");
    private readonly List<(IHost Host, CapturingLoggerProvider Logs)> _gateways = [];
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private TestSubscriber _subscriber = null!;

    public async Task InitializeAsync()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [5]);
        _simulator = await RecordingSimulator.StartAsync(plc);
        _broker = await MosquittoBroker.StartAsync(new MosquittoSettings { SharedLogFile = _logFile, LogTag = "A" });
        _subscriber = await TestSubscriber.ConnectAsync(_broker, [SparkplugEndToEndTests.Namespace + "/#"]);
    }

    public async Task DisposeAsync()
    {
        foreach ((IHost host, CapturingLoggerProvider logs) in _gateways)
        {
            await host.StopAsync();
            host.Dispose();
            output.WriteLine("gateway:" + Environment.NewLine + logs.Dump());
        }

        await _subscriber.DisposeAsync();
        await _simulator.DisposeAsync();
        output.WriteLine("mosquitto:" + Environment.NewLine + File.ReadAllText(_logFile));
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task Two_gateways_with_one_mqtt_client_id_each_say_so_once_and_reconnect_no_faster_than_their_backoff()
    {
        Dictionary<string, string?> config = MqttGatewayConfig.Create(_simulator.Port, _broker, clientId: "copied-gateway");
        await RunTwoAsync(config, "Mqtt", "copied-gateway", reconnectedEvent: MqttLog.Events.Reconnected);
    }

    [Fact]
    public async Task Two_gateways_with_one_sparkplug_identity_each_say_so_once_and_their_births_are_not_stormed()
    {
        Dictionary<string, string?> config = SparkplugEndToEndTests.Config(_simulator.Port, _broker);
        string clientId = SparkplugEndToEndTests.Group + "-" + SparkplugEndToEndTests.Node;
        IReadOnlyList<string> connections = await RunTwoAsync(config, "Sparkplug", clientId, reconnectedEvent: null);

        int births = _subscriber.Messages.Count(m => m.Topic == SparkplugEndToEndTests.NBirth);
        output.WriteLine($"{births} NBIRTH for {connections.Count} connections");
        births.Should().BeLessThanOrEqualTo(connections.Count, "a birth per connection at most: no rebirth storm");
        births.Should().BeGreaterThan(0);
    }

    /// <summary>
    /// Starts two gateways of <paramref name="config"/>, waits until each has said once that another client takes its
    /// sessions over and the broker has seen a dozen connections of <paramref name="clientId"/>, then checks each
    /// gateway's reconnections against its backoff.
    /// </summary>
    private async Task<IReadOnlyList<string>> RunTwoAsync(Dictionary<string, string?> config, string section, string clientId, int? reconnectedEvent)
    {
        config[$"{section}:Reconnect:Initial"] = Initial.ToString();
        config[$"{section}:Reconnect:Max"] = Max.ToString();
        MqttGatewayConfig.Group(config, "level", "D100");
        var clock = Stopwatch.StartNew();
        for (int i = 0; i < 2; i++)
        {
            if (section == "Mqtt")
            {
                // Each its own state directory: the files are not what is shared here.
                config["Mqtt:StateDirectory"] = MqttGatewayConfig.NewStateDirectory();
            }

            var logs = new CapturingLoggerProvider();
            IHost host = MqttGatewayConfig.Build(config, logs);
            _gateways.Add((host, logs));
            await host.StartAsync();
            await MqttGatewayConfig.Eventually(() => Status(host).State == BrokerState.Connected, "the gateway is connected", logs);
        }

        await MqttGatewayConfig.Eventually(
            () => _gateways.All(g => g.Logs.WithEvent(BrokerLog.Events.DuplicateIdentity).Count > 0) && ConnectionTimeline.Read(_logFile, clientId).Connections.Count >= 12,
            "both gateways say another client takes their sessions over, and they have taken turns a while",
            _gateways[1].Logs,
            TimeSpan.FromSeconds(90));
        output.WriteLine($"{clock.Elapsed.TotalSeconds:0.0} s");

        foreach ((IHost host, CapturingLoggerProvider logs) in _gateways)
        {
            LogEntry said = logs.WithEvent(BrokerLog.Events.DuplicateIdentity).Should().ContainSingle("said once").Subject;
            said.Level.Should().Be(Microsoft.Extensions.Logging.LogLevel.Error);
            said.Message.Should().Contain($"client id {clientId}").And.Contain($"127.0.0.1:{_broker.Port}").And.Contain($"{section}:ClientId");

            // Every takeover is followed by one wait of the backoff, never shorter, each at least the one before, up to
            // Reconnect:Max: never one reconnection per Reconnect:Initial.
            LogEntry[] takeovers = logs.Entries.Where(e => e.EventId.Id is BrokerLog.Events.DuplicateIdentity or BrokerLog.Events.DuplicateIdentityAgain).ToArray();
            double[] delays = takeovers.Select(e => Convert.ToDouble(e["RetryInSeconds"], System.Globalization.CultureInfo.InvariantCulture)).ToArray();
            output.WriteLine("delays: " + string.Join(", ", delays));
            delays.Should().BeInAscendingOrder().And.OnlyContain(d => d >= Initial.TotalSeconds && d <= Max.TotalSeconds);
            delays[^1].Should().Be(Max.TotalSeconds, "the delay grew to Reconnect:Max");
            BrokerStatus status = Status(host);
            status.DuplicateIdentity.Should().BeTrue();
            status.Connections.Should().BeLessThanOrEqualTo(takeovers.Length + 3, "one connection per wait (the first ones before the takeovers were noticed included)");
            if (reconnectedEvent is { } reconnected)
            {
                // Each reconnection came no sooner than the wait logged before it.
                foreach (LogEntry takeover in takeovers)
                {
                    LogEntry? next = logs.Entries.FirstOrDefault(e => e.EventId.Id == reconnected && e.Time > takeover.Time);
                    if (next is not null)
                    {
                        double waited = (next.Time - takeover.Time).TotalSeconds;
                        waited.Should().BeGreaterThanOrEqualTo(Convert.ToDouble(takeover["RetryInSeconds"], System.Globalization.CultureInfo.InvariantCulture) * 0.9);
                    }
                }
            }
        }

        (IReadOnlyList<string> connections, IReadOnlyList<string> overlaps) = ConnectionTimeline.Read(_logFile, clientId);
        overlaps.Should().BeEmpty("one broker: the broker itself keeps one session per client id");
        return connections;
    }

    private static BrokerStatus Status(IHost host) => host.Services.GetRequiredService<BrokerConnections>().Statuses().Single();
}
