using System.Globalization;
using System.Text.Json.Nodes;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Gateway.Tests.Telemetry;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// The gateway as a Sparkplug B edge node against Mosquitto, with the test as the host application: what it publishes
/// is decoded, and the commands it is sent are encoded, by Eclipse Tahu's JavaScript library (npm
/// <c>sparkplug-payload</c>), not by the gateway's own code. Simulated PLCs on a multidrop line record every frame.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class SparkplugEndToEndTests(ITestOutputHelper output, TahuCodecFixture fixture) : IClassFixture<TahuCodecFixture>
{
    internal const string Group = "Plant1";
    internal const string Node = "gw1";
    internal const string Namespace = "spBv1.0/" + Group;
    internal static readonly string NBirth = $"{Namespace}/NBIRTH/{Node}";
    internal static readonly string NDeath = $"{Namespace}/NDEATH/{Node}";

    private readonly TahuCodec _tahu = fixture.Codec;

    internal static string Device(string type, string device) => $"{Namespace}/{type}/{Node}/{device}";

    /// <summary>A gateway with Sparkplug alone (no JSON output) on <paramref name="broker"/>, polling the simulator at <paramref name="plcPort"/>.</summary>
    internal static Dictionary<string, string?> Config(int plcPort, MosquittoBroker broker)
    {
        // The MQTT tests' link, without the JSON output: Sparkplug alone.
        Dictionary<string, string?> config = MqttGatewayConfig.Create(plcPort, broker)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["Sparkplug:Host"] = "127.0.0.1";
        config["Sparkplug:Port"] = broker.Port.ToString(CultureInfo.InvariantCulture);
        config["Sparkplug:GroupId"] = Group;
        config["Sparkplug:EdgeNodeId"] = Node;
        config["Sparkplug:Reconnect:Initial"] = "100ms";
        config["Sparkplug:Reconnect:Max"] = "500ms";
        return config;
    }

    [Fact]
    public async Task Births_data_on_change_device_death_rebirth_and_guarded_writes_as_a_host_application_sees_them()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var press = new VirtualPlc(new VirtualPlcOptions { Units = [0] });
        press.WriteWords("D100", [5]);
        press.WriteWords("D110", [1, 2, 3]);
        press.WriteWords("D200", [0x0000, 0x41AC]); // 21.5
        press.SetBit("CIO10.03", true);
        press.WriteWords("D300", PlcWords.FromString("MIX-A7"));
        press.WriteWords("D400", [7]);
        var oven = new VirtualPlc(new VirtualPlcOptions { Units = [1] });
        oven.WriteWords("D100", [11]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(new VirtualPlcLine([press, oven]));
        Dictionary<string, string?> config = Config(simulator.Port, broker);
        config["Sparkplug:Writes:Enabled"] = "true";
        config["HostLink:Links:plc:Demotion:After"] = "1";
        config["HostLink:Links:plc:Demotion:Period"] = "1s";
        MqttGatewayConfig.Group(config, "level", "D100", "int16", writable: true);
        MqttGatewayConfig.Group(config, "levels", "D110", "int16", count: 3, writable: true);
        MqttGatewayConfig.Group(config, "temp", "D200", "float");
        MqttGatewayConfig.Group(config, "running", "CIO10.03", "bit");
        MqttGatewayConfig.Group(config, "recipe", "D300", "string", count: 8);
        MqttGatewayConfig.Group(config, "locked", "D400", "int16");
        MqttGatewayConfig.Group(config, "speed", "D100", "uint16", unit: 1);
        await using TestSubscriber app = await TestSubscriber.ConnectAsync(broker, [Namespace + "/#"]);
        var logs = new CapturingLoggerProvider();
        using IHost host = MqttGatewayConfig.Build(config, logs);
        long started = DateTimeOffset.UtcNow.ToUnixTimeMilliseconds();
        await host.StartAsync();
        try
        {
            // Births: the node (seq 0, bdSeq, the rebirth control), then each unit as a device.
            await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")) && Has(ms, Device("DBIRTH", "plc-1")), "the node and both devices are born");
            JsonObject nbirth = await Decode(app, NBirth);
            Seq(nbirth).Should().Be(0);
            string bdSeq = (string)Metric(nbirth, "bdSeq")["value"]!;
            ((string?)Metric(nbirth, "bdSeq")["type"]).Should().Be("Int64");
            ((bool?)Metric(nbirth, "Node Control/Rebirth")["value"]).Should().BeFalse();
            JsonObject dbirth = await Decode(app, Device("DBIRTH", "plc-0"));
            Seq(dbirth).Should().BeGreaterThan(0);
            // The configuration lists the groups by name; a tag of several values is one metric per value.
            Names(dbirth).Should().Equal("level", "levels/0", "levels/1", "levels/2", "locked", "recipe", "running", "temp");
            Types(dbirth).Should().Equal("Int16", "Int16", "Int16", "Int16", "Int16", "String", "Boolean", "Float");
            Value(dbirth, "level").Should().Be("5");
            Value(dbirth, "levels/1").Should().Be("2");
            Value(dbirth, "temp").Should().Be("21.5");
            Value(dbirth, "running").Should().Be("true");
            Value(dbirth, "recipe").Should().Be("MIX-A7");
            Metrics(dbirth).Select(m => (string)m["alias"]!).Should().OnlyHaveUniqueItems();
            long readAt = long.Parse((string)Metric(dbirth, "level")["timestamp"]!, CultureInfo.InvariantCulture);
            readAt.Should().BeInRange(started, DateTimeOffset.UtcNow.ToUnixTimeMilliseconds(), "a metric's timestamp is when the PLC was read");
            Value(await Decode(app, Device("DBIRTH", "plc-1")), "speed").Should().Be("11");
            string levelAlias = (string)Metric(dbirth, "level")["alias"]!;

            // Data on change: one metric changed, one DDATA with that metric alone, by alias.
            press.WriteWords("D100", [42]);
            JsonObject ddata = await DecodeWhen(app, Device("DDATA", "plc-0"), d => Metrics(d).Any(m => (string?)m["alias"] == levelAlias && ValueText(m) == "42"));
            Metrics(ddata).Should().ContainSingle("only what changed is sent");
            ((string?)Metrics(ddata)[0]["type"]).Should().Be("Int16");

            // A unit that stops answering is a device death (its metrics go stale in the host); back, a new birth.
            oven.Options.Faults.Drop = 1;
            await app.WaitUntilAsync(ms => Has(ms, Device("DDEATH", "plc-1")), "the silent unit's device dies");
            int births = app.Messages.Count(m => m.Topic == Device("DBIRTH", "plc-1"));
            oven.WriteWords("D100", [12]);
            oven.Options.Faults.Drop = 0;
            await app.WaitUntilAsync(ms => ms.Count(m => m.Topic == Device("DBIRTH", "plc-1")) > births, "the unit answers again and its device is born again");
            Value(await Decode(app, Device("DBIRTH", "plc-1")), "speed").Should().Be("12");

            // The host application asks for a rebirth: NBIRTH again (seq 0, the same bdSeq: the session goes on), then the devices.
            int nbirths = app.Messages.Count(m => m.Topic == NBirth);
            byte[] rebirth = await _tahu.EncodeAsync(new { timestamp = 1, metrics = new object[] { new { name = "Node Control/Rebirth", type = "Boolean", value = true } } });
            await app.PublishAsync($"{Namespace}/NCMD/{Node}", rebirth);
            await app.WaitUntilAsync(
                ms => ms.Count(m => m.Topic == NBirth) > nbirths && ms.Reverse().TakeWhile(m => m.Topic != NBirth).Any(m => m.Topic == Device("DBIRTH", "plc-0")),
                "births follow the rebirth request");
            JsonObject reborn = await Decode(app, NBirth);
            Seq(reborn).Should().Be(0);
            ((string?)Metric(reborn, "bdSeq")["value"]).Should().Be(bdSeq);

            // An allowlisted DCMD writes, through the same checks as a JSON write; the PLC's memory changes, and the
            // value read back comes in DDATA.
            byte[] write = await _tahu.EncodeAsync(new { timestamp = 1, metrics = new object[] { new { name = "level", type = "Int16", value = 1234 }, new { name = "levels/1", type = "Int16", value = -5 } } });
            await app.PublishAsync(Device("DCMD", "plc-0"), write);
            await MqttGatewayConfig.Eventually(() => press.ReadWords("D100", 1)[0] == 1234 && press.ReadWords("D111", 1)[0] == unchecked((ushort)-5), "the allowlisted DCMD reaches the PLC", logs);
            await DecodeWhen(app, Device("DDATA", "plc-0"), d => Metrics(d).Any(m => (string?)m["alias"] == levelAlias && ValueText(m) == "1234"));

            // Refused: a tag that is not writable, and a value in the wrong field for its type. Nothing reaches the PLC.
            int refusedBefore = logs.WithEvent(1307).Count;
            byte[] refused = await _tahu.EncodeAsync(new { timestamp = 1, metrics = new object[] { new { name = "locked", type = "Int16", value = 99 }, new { name = "level", type = "String", value = "1" } } });
            await app.PublishAsync(Device("DCMD", "plc-0"), refused);
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(1307).Count >= refusedBefore + 2, "both metrics are refused", logs);
            logs.WithEvent(1307).Skip(refusedBefore).Select(e => e.Message).Should().Satisfy(
                m => m.Contains("locked", StringComparison.Ordinal) && m.Contains("is not writable", StringComparison.Ordinal),
                m => m.Contains("level", StringComparison.Ordinal) && m.Contains("Int16", StringComparison.Ordinal));
            press.ReadWords("D400", 1)[0].Should().Be(7, "the refused write never reached the PLC");
            simulator.Received.Should().NotContain(f => f.StartsWith("@00WD0400", StringComparison.Ordinal));
            simulator.Received.Count(f => RecordingSimulator.Header(f) == "WD").Should().Be(2, "the two allowlisted writes only");

            // seq runs 0, 1, 2… from each NBIRTH, every message of the node numbered once.
            var seqs = new List<long>();
            foreach (ReceivedMessage m in app.Messages.Where(m => m.Topic != NDeath && !m.Topic.Contains("CMD/", StringComparison.Ordinal)))
            {
                seqs.Add(Seq(await _tahu.DecodeAsync(m.Bytes!)));
            }

            for (int i = 1; i < seqs.Count; i++)
            {
                if (seqs[i] != 0)
                {
                    seqs[i].Should().Be((seqs[i - 1] + 1) % 256, "message {0} follows message {1}: {2}", i, i - 1, string.Join(",", seqs));
                }
            }
        }
        finally
        {
            await host.StopAsync();
            output.WriteLine(logs.Dump());
        }

        // A clean stop: the devices die, then the node, with the session's bdSeq.
        await app.WaitUntilAsync(ms => Has(ms, NDeath), "the node's death on a clean stop");
        app.Messages.Last().Topic.Should().Be(NDeath);
    }

    [Fact]
    public async Task A_killed_gateway_is_declared_dead_by_its_will_with_the_bdSeq_of_its_birth()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var plc = new VirtualPlc();
        plc.WriteWords("D100", [5]);
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = Config(simulator.Port, broker);
        MqttGatewayConfig.Group(config, "level", "D100");
        await using TestSubscriber app = await TestSubscriber.ConnectAsync(broker, [Namespace + "/#"]);
        GatewayProcess gateway = GatewayProcess.Start(config.Select(c => $"--{c.Key}={c.Value}"));
        try
        {
            await app.WaitUntilAsync(ms => Has(ms, NBirth) && Has(ms, Device("DBIRTH", "plc-0")), "the gateway process is online", TimeSpan.FromSeconds(60));
            string bdSeq = (string)Metric(await Decode(app, NBirth), "bdSeq")["value"]!;

            await gateway.KillAsync(); // SIGKILL: no NDEATH of its own

            await app.WaitUntilAsync(ms => Has(ms, NDeath), "the broker publishes the will, NDEATH", TimeSpan.FromSeconds(60));
            JsonObject death = await Decode(app, NDeath);
            ((string?)Metric(death, "bdSeq")["value"]).Should().Be(bdSeq, "the death names the birth it ends");
            death.ContainsKey("seq").Should().BeFalse();
            app.Messages.Single(m => m.Topic == NDeath).Retain.Should().BeFalse("Sparkplug messages are never retained");
        }
        finally
        {
            output.WriteLine("gateway:" + Environment.NewLine + gateway.Output);
            await gateway.DisposeAsync();
        }
    }

    internal static bool Has(IReadOnlyList<ReceivedMessage> messages, string topic) => messages.Any(m => m.Topic == topic);

    private async Task<JsonObject> Decode(TestSubscriber app, string topic)
        => await _tahu.DecodeAsync(app.Messages.Last(m => m.Topic == topic).Bytes!);

    /// <summary>Waits for a message on <paramref name="topic"/> that, decoded, satisfies <paramref name="match"/>.</summary>
    private async Task<JsonObject> DecodeWhen(TestSubscriber app, string topic, Func<JsonObject, bool> match)
    {
        int seen = 0;
        TimeSpan patience = TimeSpan.FromSeconds(20);
        var clock = System.Diagnostics.Stopwatch.StartNew();
        while (true)
        {
            ReceivedMessage[] messages = app.Messages.Where(m => m.Topic == topic).ToArray();
            for (; seen < messages.Length; seen++)
            {
                JsonObject decoded = await _tahu.DecodeAsync(messages[seen].Bytes!);
                if (match(decoded))
                {
                    return decoded;
                }
            }

            // Decoding is asynchronous (Tahu in node), so the wait is for the next message and the loop decodes it.
            TimeSpan left = patience - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                throw new Xunit.Sdk.XunitException($"No matching message on {topic}. Received:{Environment.NewLine}{app.Dump()}");
            }

            await app.WaitUntilAsync(ms => ms.Count(m => m.Topic == topic) > seen, $"another message on {topic}", left);
        }
    }

    internal static long Seq(JsonObject payload) => long.Parse((string)payload["seq"]!, CultureInfo.InvariantCulture);

    internal static JsonObject[] Metrics(JsonObject payload) => payload["metrics"]!.AsArray().Select(m => m!.AsObject()).ToArray();

    internal static JsonObject Metric(JsonObject payload, string name) => Metrics(payload).Single(m => (string?)m["name"] == name);

    private static IEnumerable<string> Names(JsonObject payload) => Metrics(payload).Select(m => (string)m["name"]!);

    private static IEnumerable<string> Types(JsonObject payload) => Metrics(payload).Select(m => (string)m["type"]!);

    internal static string Value(JsonObject payload, string name) => ValueText(Metric(payload, name));

    internal static string ValueText(JsonObject metric) => metric["value"]!.ToJsonString().Trim('"');
}
