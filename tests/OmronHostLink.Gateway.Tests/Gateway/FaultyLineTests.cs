using System.Globalization;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using OmronHostLink.Gateway.Tests.Mqtt;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The gateway on a faulty C-mode line at 9600 bps: answers dropped, corrupted, preceded by noise, cut short, and
/// delivered out of turn (held back a second while later commands are answered). Six groups read 4 words each — the
/// same command shape — from addresses holding words no other group holds, so a value taken from another group's
/// answer would show. Every value published as good must be the group's own.
/// </summary>
[Trait("Category", "Slow")]
public sealed class FaultyLineTests(ITestOutputHelper output)
{
    private static readonly string[] Addresses = ["D100", "D310", "D1000", "D2000", "D3000", "D4000"];

    /// <summary>How long the line is polled: <c>HOSTLINK_FAULTY_LINE_SECONDS</c>, default 40.</summary>
    private static TimeSpan Duration => TimeSpan.FromSeconds(
        int.TryParse(Environment.GetEnvironmentVariable("HOSTLINK_FAULTY_LINE_SECONDS"), NumberStyles.Integer, CultureInfo.InvariantCulture, out int s) && s > 0 ? s : 40);

    [Fact]
    public async Task No_value_of_another_group_is_published_as_good_on_a_line_that_delivers_answers_out_of_turn()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions
        {
            BaudRate = 9600,
            Turnaround = TimeSpan.FromMilliseconds(5),
            Faults = new FaultOptions { Seed = 34, Drop = 0.05, Corrupt = 0.05, Noise = 0.02, Truncate = 0.02, OutOfTurn = 0.02, LateBy = TimeSpan.FromSeconds(1) },
        });
        for (int g = 0; g < Addresses.Length; g++)
        {
            plc.WriteWords(Addresses[g], Words(g));
        }

        await using RecordingSimulator simulator = await RecordingSimulator.StartAsync(plc);
        Dictionary<string, string?> config = MqttGatewayConfig.Create(simulator.Port, broker: null)
            .Where(k => !k.Key.StartsWith("Mqtt:", StringComparison.Ordinal))
            .ToDictionary(k => k.Key, k => k.Value);
        config["HostLink:Links:plc:Serial:BaudRate"] = "9600";
        config["HostLink:Links:plc:TurnaroundAllowance"] = "300ms";
        config["HostLink:Links:plc:ReadRetries"] = "2";
        for (int g = 0; g < Addresses.Length; g++)
        {
            MqttGatewayConfig.Group(config, $"g{g}", Addresses[g], type: "word", count: 4, intervalMs: 250);
        }

        var logs = new CapturingLoggerProvider();
        var outputs = new RecordingOutput();
        using IHost host = MqttGatewayConfig.Build(config, logs, s => s.AddSingleton<ITagOutput>(outputs));
        await host.StartAsync();
        try
        {
            // Wait for the faults to have happened, not for a time: until the run's share of out-of-turn answers is in.
            var started = System.Diagnostics.Stopwatch.StartNew();
            await MqttGatewayConfig.Eventually(() => started.Elapsed >= Duration && plc.FaultCounters.OutOfTurn >= 3, "the line has run its time with answers out of turn", logs, Duration + TimeSpan.FromMinutes(2));
        }
        finally
        {
            await host.StopAsync();
        }

        TagChange[] good = outputs.Tags.Where(t => t.Quality == TagQuality.Good).ToArray();
        TagChange[] wrong = good.Where(t => !Equals(Format(t.Value), Format(Words(int.Parse(t.Tag.AsSpan(1), CultureInfo.InvariantCulture))))).ToArray();
        output.WriteLine($"{Duration.TotalSeconds:0} s: {good.Length} good values published (on change), {outputs.Tags.Count(t => t.Quality != TagQuality.Good)} other outcomes, {wrong.Length} wrong; simulator {plc.FaultCounters}; {simulator.Received.Count} frames received");
        foreach (TagChange w in wrong)
        {
            output.WriteLine($"WRONG {w.Tag} {Format(w.Value)} at {w.Time:HH:mm:ss.fff}");
        }

        plc.FaultCounters.OutOfTurn.Should().BeGreaterThan(0);
        good.Select(t => t.Tag).Distinct().Should().HaveCount(Addresses.Length, "every group was read");
        wrong.Should().BeEmpty("no group's value may be published as good with another group's words");
    }

    private static ushort[] Words(int g) => [(ushort)(0x1100 * (g + 1)), (ushort)((0x1100 * (g + 1)) + 1), (ushort)((0x1100 * (g + 1)) + 2), (ushort)((0x1100 * (g + 1)) + 3)];

    private static string Format(object? value) => value switch
    {
        ushort[] words => string.Join(",", words.Select(w => w.ToString("X4", CultureInfo.InvariantCulture))),
        System.Collections.IEnumerable many => string.Join(",", many.Cast<object>().Select(o => Convert.ToUInt16(o, CultureInfo.InvariantCulture).ToString("X4", CultureInfo.InvariantCulture))),
        null => "null",
        _ => Convert.ToString(value, CultureInfo.InvariantCulture) ?? "null",
    };
}
