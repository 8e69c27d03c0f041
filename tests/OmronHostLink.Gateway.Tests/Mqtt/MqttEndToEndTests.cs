using System.Diagnostics.Metrics;
using System.Globalization;
using System.Text.Json;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>Simulator → worker (its real host) → Mosquitto → a subscriber.</summary>
[Collection(MosquittoCollection.Name)]
public sealed class MqttEndToEndTests(ITestOutputHelper output) : IAsyncLifetime
{
    private readonly List<CapturingLoggerProvider> _logs = new();
    private readonly List<IAsyncDisposable> _cleanup = new();
    private MosquittoBroker _broker = null!;

    public async Task InitializeAsync() => _broker = await MosquittoBroker.StartAsync();

    public async Task DisposeAsync()
    {
        foreach (IAsyncDisposable d in Enumerable.Reverse(_cleanup))
        {
            await d.DisposeAsync();
        }

        foreach (CapturingLoggerProvider logs in _logs)
        {
            output.WriteLine(logs.Dump());
        }

        output.WriteLine("mosquitto:" + Environment.NewLine + _broker.Log);
        await _broker.DisposeAsync();
    }

    [Fact]
    public async Task Values_are_published_retained_with_type_quality_and_read_time()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [120, unchecked((ushort)-340)]);
        plc.WriteWords("D200", [0x0000, 0x41AC]);
        plc.WriteWords("D300", PlcWords.FromString("MIX-A7"));
        plc.SetBit("CIO10.03", true);
        plc.WriteWords("D400", [0x1234]);
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "levels", "D100", "int16", count: 2);
        MqttGatewayConfig.Group(config, "temperature", "D200", "float");
        MqttGatewayConfig.Group(config, "recipe", "D300", "string", count: 8);
        MqttGatewayConfig.Group(config, "running", "CIO10.03", "bit");
        MqttGatewayConfig.Group(config, "raw", "D400", "word");
        DateTimeOffset before = DateTimeOffset.UtcNow;
        await StartWorker(config);

        // A live subscriber sees every tag once; a subscriber that comes later gets the retained messages at once.
        TestSubscriber live = await Subscriber([$"{MqttGatewayConfig.Prefix}/#"]);
        string[] tags = ["levels", "temperature", "recipe", "running", "raw"];
        await live.WaitUntilAsync(ms => tags.All(t => ms.Any(m => m.Topic == MqttGatewayConfig.Topic(t))), "every tag is published");
        TestSubscriber late = await Subscriber([$"{MqttGatewayConfig.Prefix}/#"]);
        await late.WaitUntilAsync(ms => tags.All(t => ms.Any(m => m.Topic == MqttGatewayConfig.Topic(t))), "the late subscriber gets every tag");
        late.Messages.Where(m => tags.Any(t => m.Topic == MqttGatewayConfig.Topic(t))).Should().OnlyContain(m => m.Retain, "values are retained");

        using JsonDocument levels = Payload(late, "levels");
        levels.RootElement.GetProperty("value").EnumerateArray().Select(e => e.GetInt32()).Should().Equal(120, -340);
        levels.RootElement.GetProperty("type").GetString().Should().Be("int16");
        levels.RootElement.GetProperty("quality").GetString().Should().Be("good");
        levels.RootElement.GetProperty("address").GetString().Should().Be("D100");
        levels.RootElement.TryGetProperty("error", out _).Should().BeFalse();
        string time = levels.RootElement.GetProperty("time").GetString()!;
        time.Should().MatchRegex(@"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$", "ISO 8601 UTC with milliseconds");
        DateTimeOffset read = DateTimeOffset.Parse(time, CultureInfo.InvariantCulture, DateTimeStyles.AssumeUniversal);
        read.Should().BeOnOrAfter(before.AddMilliseconds(-1)).And.BeOnOrBefore(DateTimeOffset.UtcNow);

        using JsonDocument temperature = Payload(late, "temperature");
        temperature.RootElement.GetProperty("value").GetSingle().Should().Be(21.5f);
        temperature.RootElement.GetProperty("type").GetString().Should().Be("float");
        using JsonDocument recipe = Payload(late, "recipe");
        recipe.RootElement.GetProperty("value").GetString().Should().Be("MIX-A7");
        using JsonDocument running = Payload(late, "running");
        running.RootElement.GetProperty("value").GetBoolean().Should().BeTrue();
        running.RootElement.GetProperty("address").GetString().Should().Be("CIO10.03");
        using JsonDocument raw = Payload(late, "raw");
        raw.RootElement.GetProperty("value").GetInt32().Should().Be(0x1234);

        late.Messages.Should().Contain(m => m.Topic == $"{MqttGatewayConfig.Prefix}/status/worker-test" && m.Payload == "online" && m.Retain);
        late.Messages.Should().Contain(m => m.Topic == $"{MqttGatewayConfig.Prefix}/plc/status" && m.Payload == "online" && m.Retain);
    }

    [Fact]
    public async Task A_change_in_plc_memory_appears_on_the_topic_and_an_unchanged_value_is_not_published_again()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [7]);
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "level", "D100", "int16");
        TestSubscriber subscriber = await Subscriber([MqttGatewayConfig.Topic("level")]);
        await StartWorker(config);
        await subscriber.WaitUntilAsync(ms => ms.Count == 1, "the first value");

        // Twenty more polls of the same value publish nothing.
        await simulator.WaitForAnswersAsync(simulator.Answers, 20);
        plc.WriteWords("D100", [8]);
        await subscriber.WaitUntilAsync(ms => ms.Count == 2, "the change");
        subscriber.PayloadsOn(MqttGatewayConfig.Topic("level")).Select(p => JsonDocument.Parse(p).RootElement.GetProperty("value").GetInt32())
            .Should().Equal(7, 8);
    }

    [Fact]
    public async Task Broker_stopped_and_restarted_loses_no_change_and_keeps_the_order()
    {
        var plc = new VirtualPlc();
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "counter", "D0", "uint16", intervalMs: 10);
        string topic = MqttGatewayConfig.Topic("counter");
        // A persistent session: the broker keeps the subscription and what arrives for it across its own restart.
        TestSubscriber subscriber = await Subscriber([topic], clientId: "ordered-subscriber", persistentSession: true);
        (_, CapturingLoggerProvider logs) = await StartWorker(config);
        await subscriber.WaitUntilAsync(ms => ms.Count >= 1, "the first value");

        await Count(plc, simulator, 1, 20);
        await subscriber.WaitUntilAsync(ms => ms.Any(m => Value(m) == 20), "20 before the outage");
        await _broker.StopAsync();
        await Count(plc, simulator, 21, 60); // queued by the worker while the broker is away
        await _broker.RestartAsync();
        await Count(plc, simulator, 61, 80);
        await subscriber.WaitUntilAsync(ms => ms.Any(m => Value(m) == 80), "80 after the restart", TimeSpan.FromSeconds(30));

        // Every value 0..80, in order. A value may repeat only right after itself: the message in flight when the
        // broker went away is sent again (at-least-once), and the broker may already have had it.
        int[] received = subscriber.PayloadsOn(topic).Select(p => (int)Value(p)).ToArray();
        Collapse(received).Should().Equal(Enumerable.Range(0, 81), $"received: {string.Join(",", received)}");
        logs.WithEvent(MqttLog.Events.Unreachable).Should().ContainSingle("one warning per outage");
        logs.WithEvent(MqttLog.Events.Reconnected).Should().ContainSingle();
        logs.WithEvent(MqttLog.Events.QueueOverflowed).Should().BeEmpty();
    }

    [Fact]
    public async Task A_full_queue_drops_the_oldest_and_counts_them()
    {
        var plc = new VirtualPlc();
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        config["Mqtt:QueueCapacity"] = "5";
        MqttGatewayConfig.Group(config, "counter", "D0", "uint16", intervalMs: 10);
        string topic = MqttGatewayConfig.Topic("counter");
        TestSubscriber subscriber = await Subscriber([topic], clientId: "overflow-subscriber", persistentSession: true);
        (IHost host, CapturingLoggerProvider logs) = await StartWorker(config);
        long dropped = 0;
        using var listener = new MeterListener();
        object scope = host.Services.GetRequiredService<IMeterFactory>();
        listener.InstrumentPublished = (instrument, l) =>
        {
            if (instrument.Meter.Scope == scope && instrument.Name == "hostlink.gateway.mqtt.dropped")
            {
                l.EnableMeasurementEvents(instrument);
            }
        };
        listener.SetMeasurementEventCallback<long>((_, value, _, _) => Interlocked.Add(ref dropped, value));
        listener.Start();

        OutboundQueue queue = host.Services.GetRequiredService<OutboundQueue>();
        await subscriber.WaitUntilAsync(ms => ms.Count >= 1, "the first value");
        await Count(plc, simulator, 1, 5);
        await subscriber.WaitUntilAsync(ms => ms.Any(m => Value(m) == 5), "5 before the outage");
        await MqttGatewayConfig.Eventually(() => queue.Count == 0, "the broker acknowledged everything", logs);
        await _broker.StopAsync();
        await Count(plc, simulator, 6, 25); // 20 changes into a queue of 5: the 15 oldest go
        await _broker.RestartAsync();
        await subscriber.WaitUntilAsync(ms => ms.Any(m => Value(m) == 25), "25 after the restart", TimeSpan.FromSeconds(30));
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(MqttLog.Events.QueueOverflowed).Count > 0, "the overflow episode ends when the queue has drained", logs);

        int[] received = subscriber.PayloadsOn(topic).Select(p => (int)Value(p)).ToArray();
        Collapse(received).Should().Equal([0, 1, 2, 3, 4, 5, 21, 22, 23, 24, 25], $"received: {string.Join(",", received)}");
        Interlocked.Read(ref dropped).Should().Be(15);
        queue.TotalDropped.Should().Be(15);
        LogEntry warning = logs.WithEvent(MqttLog.Events.QueueOverflowed).Should().ContainSingle("one warning per overflow episode").Subject;
        warning.Level.Should().Be(LogLevel.Warning);
        warning["Dropped"].Should().Be(15L);
        logs.WithEvent(MqttLog.Events.QueueOverflowing).Should().ContainSingle();
    }

    [Fact]
    public async Task A_plc_that_stops_answering_turns_its_tags_to_comm_error_and_the_link_status_with_them()
    {
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [42]);
        plc.WriteWords("D200", [43]);
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "a", "D100");
        MqttGatewayConfig.Group(config, "b", "D200", intervalMs: 60_000); // not polled again during the outage
        string linkStatus = $"{MqttGatewayConfig.Prefix}/plc/status";
        TestSubscriber subscriber = await Subscriber([$"{MqttGatewayConfig.Prefix}/plc/#"]);
        await StartWorker(config);
        await subscriber.WaitUntilAsync(ms => ms.Any(m => m.Topic == MqttGatewayConfig.Topic("b")) && ms.Any(m => m.Topic == linkStatus && m.Payload == "online"), "values and the link online");

        await simulator.StopAsync();
        await subscriber.WaitUntilAsync(
            ms => ms.Any(m => m.Topic == linkStatus && m.Payload == "comm-error")
                && ms.Any(m => m.Topic == MqttGatewayConfig.Topic("a") && Quality(m) == "comm-error")
                && ms.Any(m => m.Topic == MqttGatewayConfig.Topic("b") && Quality(m) == "comm-error"),
            "both tags and the link report comm-error");
        using (JsonDocument b = JsonDocument.Parse(subscriber.Messages.Last(m => m.Topic == MqttGatewayConfig.Topic("b")).Payload))
        {
            b.RootElement.GetProperty("value").GetInt32().Should().Be(43, "the last value read stands");
            b.RootElement.GetProperty("error").GetString().Should().NotBeNullOrEmpty();
        }

        plc.WriteWords("D100", [44]);
        await simulator.RestartAsync();
        await subscriber.WaitUntilAsync(
            ms => ms.Last(m => m.Topic == linkStatus).Payload == "online" && ms.Any(m => m.Topic == MqttGatewayConfig.Topic("a") && Quality(m) == "good" && Value(m) == 44),
            "the link online again with the fresh value");
        subscriber.PayloadsOn(linkStatus).Should().Equal("online", "comm-error", "online");
    }

    [Fact]
    public async Task A_clean_stop_publishes_offline_for_the_worker_and_its_links()
    {
        var plc = new VirtualPlc();
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        MqttGatewayConfig.Group(config, "a", "D100");
        TestSubscriber subscriber = await Subscriber([$"{MqttGatewayConfig.Prefix}/status/#", $"{MqttGatewayConfig.Prefix}/plc/status"]);
        (IHost host, _) = await StartWorker(config);
        await subscriber.WaitUntilAsync(ms => ms.Count(m => m.Payload == "online") == 2, "worker and link online");

        await host.StopAsync();

        await subscriber.WaitUntilAsync(ms => ms.Count(m => m.Payload == "offline") == 2, "worker and link offline");
        subscriber.PayloadsOn($"{MqttGatewayConfig.Prefix}/status/worker-test").Should().Equal("online", "offline");
        subscriber.PayloadsOn($"{MqttGatewayConfig.Prefix}/plc/status").Should().Equal("online", "offline");
    }

    [Fact]
    public async Task A_worker_stops_promptly_while_it_waits_to_reconnect()
    {
        var plc = new VirtualPlc();
        RecordingSimulator simulator = await Simulator(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, _broker);
        config["Mqtt:Reconnect:Initial"] = "00:00:30";
        config["Mqtt:Reconnect:Max"] = "00:00:30";
        MqttGatewayConfig.Group(config, "a", "D100");
        await _broker.StopAsync();
        (IHost host, CapturingLoggerProvider logs) = await StartWorker(config);
        await MqttGatewayConfig.Eventually(() => logs.WithEvent(MqttLog.Events.Unreachable).Count == 1, "the broker is reported unreachable", logs);

        var clock = System.Diagnostics.Stopwatch.StartNew();
        await host.StopAsync();

        clock.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(3), "nothing can be sent, so nothing is waited for");
        ((int?)logs.WithEvent(MqttLog.Events.Stopped).Should().ContainSingle().Subject["Queued"]).Should().BeGreaterThan(0, "what was queued is reported as not sent");
    }

    private static async Task Count(VirtualPlc plc, RecordingSimulator simulator, int from, int to)
    {
        for (int k = from; k <= to; k++)
        {
            plc.WriteWords("D0", [(ushort)k]);
            await simulator.WaitForAnswersAsync(simulator.Answers, 2);
        }
    }

    private static List<int> Collapse(IEnumerable<int> values)
    {
        var result = new List<int>();
        foreach (int v in values)
        {
            if (result.Count == 0 || result[^1] != v)
            {
                result.Add(v);
            }
        }

        return result;
    }

    private static double Value(ReceivedMessage m) => Value(m.Payload);

    private static double Value(string payload)
    {
        using JsonDocument d = JsonDocument.Parse(payload);
        return d.RootElement.GetProperty("value").GetDouble();
    }

    private static string? Quality(ReceivedMessage m)
    {
        using JsonDocument d = JsonDocument.Parse(m.Payload);
        return d.RootElement.GetProperty("quality").GetString();
    }

    private static JsonDocument Payload(TestSubscriber subscriber, string tag)
        => JsonDocument.Parse(subscriber.Messages.Last(m => m.Topic == MqttGatewayConfig.Topic(tag)).Payload);

    private async Task<RecordingSimulator> Simulator(VirtualPlc plc)
    {
        RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        _cleanup.Add(simulator);
        return simulator;
    }

    private async Task<TestSubscriber> Subscriber(string[] filters, string? clientId = null, bool persistentSession = false)
    {
        TestSubscriber subscriber = await TestSubscriber.ConnectAsync(_broker, filters, clientId, persistentSession);
        _cleanup.Add(subscriber);
        return subscriber;
    }

    private async Task<(IHost Host, CapturingLoggerProvider Logs)> StartWorker(Dictionary<string, string?> config)
    {
        var logs = new CapturingLoggerProvider();
        _logs.Add(logs);
        IHost host = MqttGatewayConfig.Build(config, logs);
        _cleanup.Add(new HostStopper(host));
        await host.StartAsync();
        return (host, logs);
    }

    /// <summary>Stops and disposes a host at the end of a test (a stopped host stops again harmlessly).</summary>
    private sealed class HostStopper(IHost host) : IAsyncDisposable
    {
        public async ValueTask DisposeAsync()
        {
            await host.StopAsync();
            host.Dispose();
        }
    }
}
