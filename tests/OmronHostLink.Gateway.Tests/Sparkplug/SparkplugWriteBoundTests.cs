using System.Globalization;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Tests.Gateway;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// A DCMD's writes are bounded as JSON commands are: a metric named many times is written once, with the value of its
/// last mention and in its place; a command of more writes than the backlog holds, or than there is room for, is
/// refused whole and logged with its count; and a flood of commands leaves the link's polls their turns. Commands are
/// encoded by Eclipse Tahu; a simulated PLC at 38400 baud records every frame.
/// </summary>
[Collection(MosquittoCollection.Name)]
public sealed class SparkplugWriteBoundTests(ITestOutputHelper output, TahuCodecFixture fixture) : IClassFixture<TahuCodecFixture>
{
    private const int Baud = 38400;
    // Long enough that a loaded test machine's pauses (measured up to 0.5 s) stay inside the bound of 2 intervals, short
    // enough that the flood (2 s and more) lasts several.
    private const int PollMs = 500;
    private const int CommandRefused = 1314;
    private readonly TahuCodec _tahu = fixture.Codec;

    [Fact]
    public async Task A_dcmd_writes_each_metric_once_is_bounded_and_a_flood_leaves_polling_its_turns()
    {
        await using MosquittoBroker broker = await MosquittoBroker.StartAsync();
        var plc = new VirtualPlc(new VirtualPlcOptions { BaudRate = Baud });
        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = SparkplugEndToEndTests.Config(simulator.Port, broker);
        config["HostLink:Links:plc:Serial:BaudRate"] = Baud.ToString(CultureInfo.InvariantCulture);
        config["Sparkplug:Writes:Enabled"] = "true";
        MqttGatewayConfig.Group(config, "level", "D100", writable: true, intervalMs: PollMs);
        MqttGatewayConfig.Group(config, "levels", "D110", count: 3, writable: true, intervalMs: PollMs);
        MqttGatewayConfig.Group(config, "many", "D1000", count: 300, writable: true, intervalMs: 3_600_000); // read once: its 300 words would take a poll's turn
        MqttGatewayConfig.Group(config, "watch", "D200", intervalMs: PollMs);
        await using TestSubscriber app = await TestSubscriber.ConnectAsync(broker, [SparkplugEndToEndTests.Namespace + "/#"]);
        var logs = new CapturingLoggerProvider();
        var polls = new RecordingOutput();
        using IHost host = MqttGatewayConfig.Build(config, logs, services => services.AddSingleton<Outputs.ITagOutput>(polls));
        string dcmd = SparkplugEndToEndTests.Device("DCMD", "plc-0");
        await host.StartAsync();
        try
        {
            await app.WaitUntilAsync(ms => SparkplugEndToEndTests.Has(ms, SparkplugEndToEndTests.Device("DBIRTH", "plc-0")), "the device is born");

            // 1,000 metrics, four of them distinct: each is written once, with its last value, in the place of its last mention.
            var metrics = new List<object>();
            for (int i = 1; i <= 996; i++)
            {
                metrics.Add(new { name = "level", type = "Int16", value = i });
            }

            metrics.Add(new { name = "levels/0", type = "Int16", value = 10 });
            metrics.Add(new { name = "levels/1", type = "Int16", value = 11 });
            metrics.Add(new { name = "levels/2", type = "Int16", value = 12 });
            metrics.Add(new { name = "level", type = "Int16", value = 997 });
            int framesBefore = simulator.Received.Count;
            await app.PublishAsync(dcmd, await _tahu.EncodeAsync(new { timestamp = 1, metrics }));
            await MqttGatewayConfig.Eventually(() => plc.ReadWords("D100", 1)[0] == 997 && plc.ReadWords("D112", 1)[0] == 12, "the merged writes reach the PLC", logs);
            string[] writes = simulator.Received.Skip(framesBefore).Where(f => RecordingSimulator.Header(f) == "WD").Select(f => f.Substring(5, 4)).ToArray();
            writes.Should().Equal(["0110", "0111", "0112", "0100"], "each metric once, level where it was last named");

            // More distinct metrics than the backlog holds: refused whole, with the count, and nothing written.
            int refusedBefore = logs.WithEvent(CommandRefused).Count;
            object[] all = Enumerable.Range(0, 300).Select(i => (object)new { name = $"many/{i}", type = "Int16", value = 7 }).ToArray();
            await app.PublishAsync(dcmd, await _tahu.EncodeAsync(new { timestamp = 1, metrics = all }));
            await MqttGatewayConfig.Eventually(() => logs.WithEvent(CommandRefused).Count > refusedBefore, "the oversized command is refused", logs);
            logs.WithEvent(CommandRefused)[refusedBefore].Message.Should().Be(
                "Sparkplug: DCMD plc-0 refused whole, 300 metric write(s), nothing sent to the PLC: a DCMD may carry at most 256 metric writes (each metric counted once)");

            // A flood: 20 commands of 100 writes each. What does not fit is refused whole; what fits is written, and
            // meanwhile the other groups are polled on time.
            refusedBefore = logs.WithEvent(CommandRefused).Count;
            framesBefore = simulator.Received.Count;
            object[] hundred = Enumerable.Range(0, 100).Select(i => (object)new { name = $"many/{i}", type = "Int16", value = 3 }).ToArray();
            byte[] payload = await _tahu.EncodeAsync(new { timestamp = 1, metrics = hundred });
            DateTimeOffset floodStart = DateTimeOffset.UtcNow;
            for (int i = 0; i < 20; i++)
            {
                await app.PublishAsync(dcmd, payload);
            }

            await MqttGatewayConfig.Eventually(
                () => logs.WithEvent(CommandRefused).Count - refusedBefore + (Writes(simulator, framesBefore) / 100) == 20,
                "every command of the flood is written or refused",
                logs,
                TimeSpan.FromSeconds(60));
            DateTimeOffset floodEnd = DateTimeOffset.UtcNow;
            int refused = logs.WithEvent(CommandRefused).Count - refusedBefore;
            int written = Writes(simulator, framesBefore);
            output.WriteLine($"flood: {20 - refused} commands written ({written} writes), {refused} refused, {(floodEnd - floodStart).TotalSeconds:0.0} s");
            refused.Should().BeGreaterThan(0, "20 × 100 writes do not fit in a backlog of 256");
            written.Should().Be((20 - refused) * 100, "a command is written whole or not at all, each metric once");
            logs.WithEvent(CommandRefused).Skip(refusedBefore).Should().OnlyContain(e => e.Message.Contains("refused whole, 100 metric write(s)", StringComparison.Ordinal)
                && e.Message.Contains("and at most 256 may; send it again later", StringComparison.Ordinal));
            // The last write's frame reaches the PLC before its answer releases its place in the backlog.
            var commands = host.Services.GetRequiredService<OmronHostLink.Gateway.Sparkplug.SparkplugCommands>();
            await MqttGatewayConfig.Eventually(() => commands.Waiting == 0, "the backlog is given back", logs);

            DateTimeOffset[] watchPolls = polls.Tags
                .Where(t => t.Tag == "watch" && t.Quality == TagQuality.Good && t.Time >= floodStart && t.Time <= floodEnd)
                .Select(t => t.Time).ToArray();
            watchPolls.Length.Should().BeGreaterThan(2, "the flood lasts several poll intervals");
            TimeSpan longest = watchPolls.Zip(watchPolls.Skip(1), (a, b) => b - a).Max();
            output.WriteLine($"watch polled {watchPolls.Length} times during the flood; longest gap {longest.TotalMilliseconds:0} ms (interval {PollMs} ms)");
            // A poll waits for the write on the line at most; a loaded machine may still wake its timer a cycle late.
            // Writes that did not take turns would hold the polls off for the whole flood (seconds).
            longest.Should().BeLessThan(TimeSpan.FromMilliseconds(3 * PollMs), "the writes take turns with the polls");
        }
        finally
        {
            await host.StopAsync();
        }
    }

    /// <summary>Writes to the 300-word tag since frame <paramref name="since"/>.</summary>
    private static int Writes(RecordingSimulator simulator, int since)
        => simulator.Received.Skip(since).Count(f => RecordingSimulator.Header(f) == "WD" && string.CompareOrdinal(f, 5, "1000", 0, 4) >= 0);
}
