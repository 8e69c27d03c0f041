using System.Globalization;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Sparkplug.Wire;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Telemetry;
using OmronHostLink.Simulator;
using Xunit.Abstractions;
using static OmronHostLink.Gateway.Tests.Sparkplug.SparkplugEndToEndTests;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// Store-and-forward against Mosquitto, with the test as the primary host application (its STATE) and as a host that
/// decodes every message with Eclipse Tahu (<see cref="SparkplugHostView"/>): after the primary host's outage a tag
/// that changed every 100 ms is seen with every change exactly once — live ones live, the outage's as history
/// (<c>is_historical</c>) in the order they were read — with no seq or alias breach; the same across a SIGKILL of the
/// gateway during the outage with the durable store; and a store over its bound announces how many it dropped.
/// </summary>
/// <remarks>
/// The outage of the first test lasts <c>OHL_SPARKPLUG_OUTAGE</c> (a duration, <c>60s</c>; default <c>3s</c> in the
/// suite), counted in changes the gateway has read (ten a second), not slept.
/// </remarks>
[Collection(MosquittoCollection.Name)]
public sealed class SparkplugStoreAndForwardTests(ITestOutputHelper output, TahuCodecFixture fixture) : IClassFixture<TahuCodecFixture>, IAsyncLifetime
{
    private const string HostId = "scada";
    private const string StateTopic = "spBv1.0/STATE/" + HostId;
    private const long Session1 = 1_700_000_000_000;
    private const long Session2 = 1_700_000_600_000;

    private readonly TahuCodec _tahu = fixture.Codec;
    private readonly VirtualPlc _plc = new();
    private readonly CapturingLoggerProvider _logs = new();
    private MosquittoBroker _broker = null!;
    private RecordingSimulator _simulator = null!;
    private TestSubscriber _app = null!;
    private IHost? _host;
    private readonly List<GatewayProcess> _processes = [];

    private static TimeSpan Outage
        => Environment.GetEnvironmentVariable("OHL_SPARKPLUG_OUTAGE") is { Length: > 0 } text && Duration.TryParse(text, out TimeSpan outage, out _)
            ? outage
            : TimeSpan.FromSeconds(3);

    public async Task InitializeAsync()
    {
        _plc.WriteWords("D100", [0]);
        _broker = await MosquittoBroker.StartAsync();
        _simulator = await RecordingSimulator.StartAsync(_plc);
        _app = await TestSubscriber.ConnectAsync(_broker, [Namespace + "/#"]);
    }

    public async Task DisposeAsync()
    {
        if (_host is not null)
        {
            await _host.StopAsync();
            _host.Dispose();
        }

        output.WriteLine(_logs.Dump());
        foreach (GatewayProcess process in _processes)
        {
            output.WriteLine($"gateway {process.Id}:{Environment.NewLine}{process.Output}");
            await process.DisposeAsync();
        }

        await _app.DisposeAsync();
        await _simulator.DisposeAsync();
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task After_a_primary_host_outage_the_host_sees_every_change_once_the_outage_as_history_in_the_order_read()
    {
        int outageChanges = (int)(Outage.TotalSeconds * 10);
        await HostStateAsync(online: true, Session1);
        _host = MqttGatewayConfig.Build(Config(), _logs);
        await _host.StartAsync();
        await _app.WaitUntilAsync(ms => Has(ms, Device("DBIRTH", "plc-0")), "the node is born");
        SparkplugNode node = _host.Services.GetRequiredService<SparkplugNode>();

        // A tag that changes every 100 ms: the stimulus, paced by a timer.
        using var changes = new CancellationTokenSource();
        int last = 0;
        Task driver = Task.Run(async () =>
        {
            using var timer = new PeriodicTimer(TimeSpan.FromMilliseconds(100));
            try
            {
                while (await timer.WaitForNextTickAsync(changes.Token))
                {
                    _plc.WriteWords("D100", [(ushort)Interlocked.Increment(ref last)]);
                }
            }
            catch (OperationCanceledException)
            {
                // The outage is over.
            }
        });

        await WaitForReadsAsync(10, "live changes");
        await HostStateAsync(online: false, Session1);
        await _app.WaitUntilAsync(ms => Has(ms, NDeath), "the node ends its session");
        int atOutage = Read().Count;
        await WaitForReadsAsync(atOutage + outageChanges, $"{outageChanges} changes during the outage", Outage * 4 + TimeSpan.FromSeconds(30));

        await HostStateAsync(online: true, Session2);
        await _app.WaitUntilAsync(ms => ms.Count(m => m.Topic == NBirth) == 2, "the node is born again");
        int atReturn = Read().Count;
        await MqttGatewayConfig.Eventually(() => node.Store.Stored == 0 && Read().Count >= atReturn + 10, "the history is published and live changes follow", _logs, Outage * 2 + TimeSpan.FromSeconds(30));
        await changes.CancelAsync();
        await driver;
        int final = Volatile.Read(ref last);
        await WaitForReadsOfAsync(final);
        await _app.WaitUntilAsync(ms => Carries(ms, final, historical: false), "the last change arrives live");

        SparkplugHostView view = await SparkplugHostView.ReadAsync(_tahu, _app.Messages);
        view.Violations.Should().BeEmpty();
        List<int> read = Read();
        output.WriteLine($"{read.Count} changes read, {outageChanges} during the outage; {view.Of("counter").Count(s => s.Historical)} received as history");
        AssertEveryChangeOnce(view, read);
        int secondBirth = _app.Messages.Select((m, i) => (m, i)).Where(x => x.m.Topic == NBirth).Skip(1).First().i;
        HostSample[] history = view.Of("counter").Where(s => s.Historical).ToArray();
        history.Length.Should().BeGreaterThanOrEqualTo(outageChanges - 1, "the outage's changes, but the one the birth carries");
        history.Should().OnlyContain(s => s.Index > secondBirth, "history follows the births");
        history.Select(s => s.Timestamp).Should().BeInAscendingOrder("history comes in the order the PLC was read");
        history.Select(s => int.Parse(s.Value, CultureInfo.InvariantCulture)).Should().BeInAscendingOrder();
        view.Of("counter").Where(s => !s.Historical && !s.Birth && s.Index > secondBirth).Should().NotBeEmpty("live data goes on after the births");
    }

    [Fact]
    public async Task With_the_durable_store_the_changes_of_an_outage_survive_a_SIGKILL_and_arrive_once_as_history()
    {
        string state = MqttGatewayConfig.NewStateDirectory();
        await HostStateAsync(online: true, Session1);
        GatewayProcess first = await StartProcessAsync(state);
        await _app.WaitUntilAsync(ms => Has(ms, Device("DBIRTH", "plc-0")), "the first gateway is born", TimeSpan.FromSeconds(60));
        await StepAsync(first, 1, 5);

        await HostStateAsync(online: false, Session1);
        await _app.WaitUntilAsync(ms => Has(ms, NDeath), "the node ends its session");
        await StepAsync(first, 6, 25);
        await _simulator.WaitForAnswersAsync(_simulator.Answers, 3);
        await first.KillAsync();

        // The PLC changes while no gateway runs; the second one reads it first.
        _plc.WriteWords("D100", [26]);
        GatewayProcess second = await StartProcessAsync(state);
        (await second.WaitForOutputAsync("20 change(s) from the previous run are published as history", TimeSpan.FromSeconds(30))).Should().BeTrue(second.Output);
        (await second.WaitForOutputAsync("plc/counter: unit 0 D100 = 26", TimeSpan.FromSeconds(30))).Should().BeTrue(second.Output);
        await StepAsync(second, 27, 35);

        await HostStateAsync(online: true, Session2);
        await _app.WaitUntilAsync(ms => HistoricalCount(ms) == 29, "the history of both runs, but the value the birth carries", TimeSpan.FromSeconds(60));
        await StepAsync(second, 36, 40);
        await _app.WaitUntilAsync(ms => Carries(ms, 40, historical: false), "the last change arrives live");

        SparkplugHostView view = await SparkplugHostView.ReadAsync(_tahu, _app.Messages);
        view.Violations.Should().BeEmpty();
        AssertEveryChangeOnce(view, [.. Enumerable.Range(0, 41)]);
        view.Of("counter").Where(s => s.Historical).Select(s => int.Parse(s.Value, CultureInfo.InvariantCulture)).Should().Equal(Enumerable.Range(6, 29), "the outage's changes of both runs, in order");
        view.Of("counter").Where(s => s.Birth).Select(s => s.Value).Should().Equal("0", "35");
        view.Of("counter").Where(s => s.Historical).Select(s => s.Timestamp).Should().BeInAscendingOrder();
    }

    [Fact]
    public async Task A_store_over_its_bound_drops_the_oldest_and_announces_how_many()
    {
        await HostStateAsync(online: true, Session1);
        Dictionary<string, string?> config = Config();
        config["Sparkplug:StoreAndForward:Capacity"] = "10";
        _host = MqttGatewayConfig.Build(config, _logs);
        await _host.StartAsync();
        await _app.WaitUntilAsync(ms => Has(ms, Device("DBIRTH", "plc-0")), "the node is born");

        await HostStateAsync(online: false, Session1);
        await _app.WaitUntilAsync(ms => Has(ms, NDeath), "the node ends its session");
        for (int k = 1; k <= 25; k++)
        {
            _plc.WriteWords("D100", [(ushort)k]);
            await WaitForReadsOfAsync(k);
        }

        await HostStateAsync(online: true, Session2);
        await _app.WaitUntilAsync(ms => HistoricalCount(ms) == 9 && ms.Count(m => m.Topic == NBirth) == 2, "the ten newest changes, but the birth's, as history");

        SparkplugHostView view = await SparkplugHostView.ReadAsync(_tahu, _app.Messages);
        view.Violations.Should().BeEmpty();
        view.DroppedAnnounced.Should().Equal([0, 15], "the second NBIRTH announces the fifteen oldest changes dropped");
        view.Of("counter").Where(s => s.Historical).Select(s => s.Value).Should().Equal(Enumerable.Range(16, 9).Select(v => v.ToString(CultureInfo.InvariantCulture)));
        _logs.WithEvent(1320).Should().ContainSingle("the overflow is said when it starts");
        await MqttGatewayConfig.Eventually(() => _logs.WithEvent(1321).Count == 1, "and with its count when the store is empty again", _logs, TimeSpan.FromSeconds(60));
        _logs.WithEvent(1321)[0].Message.Should().StartWith("Sparkplug: 15 change(s) were dropped");
    }

    /// <summary>Every value read is received once: in a birth, live, or as history — never twice, never missing.</summary>
    private static void AssertEveryChangeOnce(SparkplugHostView view, IReadOnlyList<int> read)
    {
        HostSample[] samples = view.Of("counter").ToArray();
        var received = samples.GroupBy(s => int.Parse(s.Value, CultureInfo.InvariantCulture)).ToDictionary(g => g.Key, g => g.ToArray());
        read.Where(v => !received.ContainsKey(v)).Should().BeEmpty("every change read reaches the host");
        received.Where(r => r.Value.Length > 1).Select(r => $"{r.Key} x{r.Value.Length}").Should().BeEmpty("no change reaches the host twice");
        received.Keys.Where(v => !read.Contains(v)).Should().BeEmpty("nothing the gateway did not read");
    }

    /// <summary>The counter's values the in-process gateway has read, in order (its OnChange log).</summary>
    private List<int> Read()
        => _logs.WithEvent(1001).Where(e => (string?)e["Group"] == "counter").Select(e => int.Parse((string)e["Values"]!, CultureInfo.InvariantCulture)).ToList();

    private Task WaitForReadsAsync(int count, string what, TimeSpan? patience = null)
        => MqttGatewayConfig.Eventually(() => Read().Count >= count, what, _logs, patience ?? TimeSpan.FromSeconds(60));

    private Task WaitForReadsOfAsync(int value)
        => MqttGatewayConfig.Eventually(() => Read().Contains(value), $"the gateway reads {value}", _logs, TimeSpan.FromSeconds(30));

    /// <summary>Writes each value in turn, the next only once the gateway process has read this one.</summary>
    private async Task StepAsync(GatewayProcess gateway, int from, int to)
    {
        for (int k = from; k <= to; k++)
        {
            _plc.WriteWords("D100", [(ushort)k]);
            string read = $"plc/counter: unit 0 D100 = {k}";
            (await gateway.WaitForLineAsync(l => l.EndsWith(read, StringComparison.Ordinal), TimeSpan.FromSeconds(30))).Should().NotBeNull(gateway.Output);
        }
    }

    private Task HostStateAsync(bool online, long timestamp)
        => _app.PublishAsync(StateTopic, $"{{\"online\":{(online ? "true" : "false")},\"timestamp\":{timestamp}}}", retain: true);

    private Dictionary<string, string?> Config()
    {
        Dictionary<string, string?> config = SparkplugEndToEndTests.Config(_simulator.Port, _broker);
        config["Sparkplug:PrimaryHostId"] = HostId;
        config["Sparkplug:StateDirectory"] = MqttGatewayConfig.NewStateDirectory();
        // History published leaves the store 1.5 x keep-alive later: 6 s.
        config["Sparkplug:KeepAlive"] = "4s";
        MqttGatewayConfig.Group(config, "counter", "D100", "uint16");
        return config;
    }

    private async Task<GatewayProcess> StartProcessAsync(string state)
    {
        GatewayProcess gateway = GatewayProcess.Start(
            Config().Where(c => c.Key != "Sparkplug:StateDirectory").Select(c => $"--{c.Key}={c.Value}").Concat(
            [
                $"--Sparkplug:StateDirectory={state}",
                "--Sparkplug:StoreAndForward:Durable=true",
                "--Logging:LogLevel:Default=Information",
            ]));
        _processes.Add(gateway);
        (await gateway.WaitForOutputAsync("link plc: polling", TimeSpan.FromSeconds(60))).Should().BeTrue(gateway.Output);
        return gateway;
    }

    /// <summary>How many historical metrics the DDATA messages received carry (read with the gateway's own decoder, only to wait).</summary>
    private static int HistoricalCount(IReadOnlyList<ReceivedMessage> messages)
        => Data(messages).Count(m => m.IsHistorical);

    private static bool Carries(IReadOnlyList<ReceivedMessage> messages, int value, bool historical)
        => Data(messages).Any(m => m.IntValue == value && m.IsHistorical == historical);

    private static IEnumerable<Payload.Types.Metric> Data(IReadOnlyList<ReceivedMessage> messages)
        => messages.Where(m => m.Topic == Device("DDATA", "plc-0")).SelectMany(m => Payload.Parser.ParseFrom(m.Bytes).Metrics);
}
