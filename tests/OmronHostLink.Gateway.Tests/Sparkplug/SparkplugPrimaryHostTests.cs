using System.Text.Json.Nodes;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using Xunit.Abstractions;
using static OmronHostLink.Gateway.Tests.Sparkplug.SparkplugEndToEndTests;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// <c>Sparkplug:PrimaryHostId</c> against Mosquitto: the test is the primary host application, publishing its retained
/// STATE (<c>spBv1.0/STATE/{id}</c>, Sparkplug 3.0 JSON) with its own client, and reading the node's messages with Eclipse
/// Tahu's decoder. Without the setting the births come at once (<see cref="SparkplugEndToEndTests"/>).
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class SparkplugPrimaryHostTests(ITestOutputHelper output, TahuCodecFixture fixture) : IClassFixture<TahuCodecFixture>
{
    private const int Waiting = 1310;
    private const int HostOnline = 1311;
    private const int HostOffline = 1312;
    private const int StateIgnored = 1313;

    /// <summary>Long enough for births that were not held back to arrive, on a loaded machine, once the node is connected.</summary>
    /// <summary>Polls that pass before "nothing was published" is asserted.</summary>
    private const int QuietPolls = 10;

    private readonly TahuCodec _tahu = fixture.Codec;

    private static string StateTopic(string hostId) => $"spBv1.0/STATE/{hostId}";

    private static string State(bool online, long timestamp) => $"{{\"online\":{(online ? "true" : "false")},\"timestamp\":{timestamp}}}";

    [Fact]
    public async Task The_births_wait_for_the_primary_host_to_be_online_and_carry_the_values_read_meanwhile()
    {
        const string hostId = "scada-wait";
        await using Rig rig = await Rig.StartAsync(hostId, online: null, output);
        (VirtualPlc plc, RecordingSimulator simulator, TestSubscriber app, CapturingLoggerProvider logs, IHost host) = rig;
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(Waiting).Count == 1, "the node is connected and waits for the primary host", logs);

        // A STATE of Sparkplug before 3.0 (plain text) is not the JSON of 3.0: logged, ignored, still waiting.
        await app.PublishAsync(StateTopic(hostId), "ONLINE", retain: true);
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(StateIgnored).Count == 1, "the malformed STATE is logged", logs);

        // The value changes while the host is away: the node reads it, publishes nothing.
        plc.WriteWords("D100", [6]);
        int frames = simulator.Received.Count;
        await MqttGatewayConfig.Eventually(() => simulator.Received.Count > frames + 2, "the PLC is read after the change", logs);

        // Several more polls are the proof that the node had its chances to publish.
        int polled = simulator.Received.Count;
        await MqttGatewayConfig.Eventually(() => simulator.Received.Count >= polled + QuietPolls, "the node polls on while the host is away", logs);
        app.Messages.Should().NotContain(m => m.Topic.StartsWith(Namespace + "/", StringComparison.Ordinal), "nothing is published before the primary host is online");

        await app.PublishAsync(StateTopic(hostId), State(online: true, 1_700_000_000_000), retain: true);

        await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")), "the births follow the online STATE");
        app.Messages[0].Topic.Should().Be(NBirth, "NBIRTH is the node's first message");
        ((string?)Metric(await DecodeAsync(app, NBirth), "bdSeq")["value"]).Should().Be("0");
        Value(await DecodeAsync(app, Device("DBIRTH", "plc-0")), "level").Should().Be("6", "the birth carries the value read while the host was away");
        logs.WithEvent(HostOnline).Should().ContainSingle();
        // The node counts itself online once its births are published, which can be after the subscriber has received them.
        SparkplugEdgeNode edgeNode = host.Services.GetRequiredService<SparkplugEdgeNode>();
        await MqttGatewayConfig.Eventually(() => edgeNode.IsOnline, "the node is online once its births are published", logs);
    }

    [Fact]
    public async Task An_offline_primary_host_ends_the_session_and_its_return_starts_one_with_the_next_bdSeq()
    {
        const string hostId = "scada-offline";
        await using Rig rig = await Rig.StartAsync(hostId, online: 1_700_000_000_000, output);
        (_, RecordingSimulator simulator, TestSubscriber app, CapturingLoggerProvider logs, IHost host) = rig;
        SparkplugEdgeNode node = host.Services.GetRequiredService<SparkplugEdgeNode>();
        await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")), "the node is born");
        string bdSeq = (string)Metric(await DecodeAsync(app, NBirth), "bdSeq")["value"]!;

        // The host's will: offline, with the timestamp of the session it ends (the same as its online STATE's).
        await app.PublishAsync(StateTopic(hostId), State(online: false, 1_700_000_000_000), retain: true);

        await app.WaitUntilAsync(ms => Has(ms, NDeath), "the node publishes NDEATH");
        ((string?)Metric(await DecodeAsync(app, NDeath), "bdSeq")["value"]).Should().Be(bdSeq, "the death ends the birth's session");
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(Waiting).Count == 2, "the node disconnects, reconnects and waits again", logs);
        logs.WithEvent(HostOffline).Should().ContainSingle();
        node.IsOnline.Should().BeFalse();
        int polledOffline = simulator.Received.Count;
        await MqttGatewayConfig.Eventually(() => simulator.Received.Count >= polledOffline + QuietPolls, "the node polls on while the host is offline", logs);
        app.Messages.Count(m => m.Topic == NBirth).Should().Be(1, "no birth while the retained STATE says offline");

        await app.PublishAsync(StateTopic(hostId), State(online: true, 1_700_000_060_000), retain: true);

        await app.WaitUntilAsync(
            ms => ms.Count(m => m.Topic == NBirth) == 2 && ms.SkipWhile(m => m.Topic != NBirth).Skip(1).SkipWhile(m => m.Topic != NBirth).Any(m => m.Topic == Device("DBIRTH", "plc-0")),
            "the node and its device are born again");
        JsonObject reborn = await DecodeAsync(app, NBirth);
        ((string?)Metric(reborn, "bdSeq")["value"]).Should().Be((long.Parse(bdSeq, System.Globalization.CultureInfo.InvariantCulture) + 1).ToString(System.Globalization.CultureInfo.InvariantCulture), "a new connection, a new bdSeq");
        Seq(reborn).Should().Be(0);
        app.Messages.Count(m => m.Topic == NDeath).Should().Be(1, "the node disconnected cleanly: the broker did not publish its will as well");
    }

    [Fact]
    public async Task An_offline_state_older_than_the_online_one_is_ignored()
    {
        const string hostId = "scada-stale";
        await using Rig rig = await Rig.StartAsync(hostId, online: 1_700_000_060_000, output);
        (VirtualPlc plc, _, TestSubscriber app, CapturingLoggerProvider logs, _) = rig;
        await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")), "the node is born");
        string alias = (string)Metric(await DecodeAsync(app, Device("DBIRTH", "plc-0")), "level")["alias"]!;

        // The late will of a host session the host has already replaced.
        await app.PublishAsync(StateTopic(hostId), State(online: false, 1_700_000_000_000), retain: false);
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(StateIgnored).Count == 1, "the older STATE is logged as ignored", logs);
        logs.WithEvent(StateIgnored)[0].Message.Should().Contain("older");

        // The session goes on: a change is published as data.
        plc.WriteWords("D100", [77]);
        await app.WaitUntilAsync(ms => ms.Any(m => m.Topic == Device("DDATA", "plc-0")), "the change is published");
        JsonObject ddata = await DecodeAsync(app, Device("DDATA", "plc-0"));
        ((string?)Metrics(ddata)[0]["alias"]).Should().Be(alias);
        app.Messages.Should().NotContain(m => m.Topic == NDeath);
        app.Messages.Count(m => m.Topic == NBirth).Should().Be(1);
        logs.WithEvent(HostOffline).Should().BeEmpty();
        logs.WithEvent(Waiting).Should().ContainSingle("the node never reconnected");
    }

    [Fact]
    public async Task A_legacy_primary_host_is_followed_on_STATE_id_with_plain_ONLINE_and_OFFLINE()
    {
        const string hostId = "scada-legacy";
        await using Rig rig = await Rig.StartAsync(hostId, online: null, output, legacy: true);
        (_, _, TestSubscriber app, CapturingLoggerProvider logs, IHost host) = rig;
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(Waiting).Count == 1, "the node waits for the primary host", logs);
        logs.WithEvent(Waiting)[0].Message.Should().Contain("(STATE/scada-legacy)", "Sparkplug 2.2's topic, outside spBv1.0");

        // Sparkplug 3.0 JSON on the 3.0 topic is not what this host publishes: the node does not even listen there.
        await app.PublishAsync(StateTopic(hostId), State(online: true, 1_700_000_000_000), retain: true);
        await app.PublishAsync("STATE/" + hostId, "ONLINE", retain: true);

        await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")), "the births follow ONLINE");
        logs.WithEvent(HostOnline).Should().ContainSingle();
        // The node counts itself online once its births are published, which can be after the subscriber has received them.
        SparkplugEdgeNode edgeNode = host.Services.GetRequiredService<SparkplugEdgeNode>();
        await MqttGatewayConfig.Eventually(() => edgeNode.IsOnline, "the node is online once its births are published", logs);

        await app.PublishAsync("STATE/" + hostId, "OFFLINE", retain: true);

        await app.WaitUntilAsync(ms => Has(ms, NDeath), "OFFLINE ends the session with NDEATH");
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(Waiting).Count == 2, "the node reconnects and waits again", logs);
        logs.WithEvent(HostOffline).Should().ContainSingle();
        logs.WithEvent(StateIgnored).Should().BeEmpty();
    }

    private async Task<JsonObject> DecodeAsync(TestSubscriber app, string topic)
        => await _tahu.DecodeAsync(app.Messages.Last(m => m.Topic == topic).Bytes!);

    /// <summary>
    /// Mosquitto, a PLC with D100 = 5 polled as the tag "level", the test's host application client, and the gateway with
    /// <c>Sparkplug:PrimaryHostId</c>, started — after the host's retained online STATE of timestamp
    /// <paramref name="online"/>, if given. Disposing it stops the gateway, writes its log to the test's output, then
    /// stops the rest.
    /// </summary>
    private sealed class Rig : IAsyncDisposable
    {
        private MosquittoBroker _broker = null!;
        private ITestOutputHelper? _output;

        public VirtualPlc Plc { get; } = new();

        public RecordingSimulator Simulator { get; private set; } = null!;

        public TestSubscriber App { get; private set; } = null!;

        public CapturingLoggerProvider Logs { get; } = new();

        public IHost Host { get; private set; } = null!;

        public static async Task<Rig> StartAsync(string hostId, long? online, ITestOutputHelper output, bool legacy = false)
        {
            var rig = new Rig { _output = output };
            try
            {
                rig.Plc.WriteWords("D100", [5]);
                rig._broker = await MosquittoBroker.StartAsync();
                rig.Simulator = await RecordingSimulator.StartAsync(rig.Plc);
                Dictionary<string, string?> config = Config(rig.Simulator.Port, rig._broker);
                config["Sparkplug:PrimaryHostId"] = hostId;
                if (legacy)
                {
                    config["Sparkplug:PrimaryHostLegacyState"] = "true";
                }

                MqttGatewayConfig.Group(config, "level", "D100");
                rig.App = await TestSubscriber.ConnectAsync(rig._broker, [Namespace + "/#"]);
                if (online is { } timestamp)
                {
                    // The host is up before the node: its retained STATE is there when the node subscribes.
                    await rig.App.PublishAsync(StateTopic(hostId), State(online: true, timestamp), retain: true);
                }

                rig.Host = MqttGatewayConfig.Build(config, rig.Logs);
                await rig.Host.StartAsync();
                return rig;
            }
            catch
            {
                await rig.DisposeAsync();
                throw;
            }
        }

        public void Deconstruct(out VirtualPlc plc, out RecordingSimulator simulator, out TestSubscriber app, out CapturingLoggerProvider logs, out IHost host)
            => (plc, simulator, app, logs, host) = (Plc, Simulator, App, Logs, Host);

        public async ValueTask DisposeAsync()
        {
            if (Host is not null)
            {
                await Host.StopAsync();
                Host.Dispose();
            }

            _output?.WriteLine(Logs.Dump());

            if (App is not null)
            {
                await App.DisposeAsync();
            }

            if (Simulator is not null)
            {
                await Simulator.DisposeAsync();
            }

            if (_broker is not null)
            {
                await _broker.DisposeAsync();
            }
        }
    }
}
