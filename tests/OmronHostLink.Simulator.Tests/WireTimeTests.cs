using System.Diagnostics;
using OmronHostLink.Simulator;
using Xunit.Abstractions;

namespace OmronHostLink.Simulator.Tests;

/// <summary>Wire-time emulation and PLC turnaround, measured on the real clock (the pacer's schedule itself: <see cref="WirePacerScheduleTests"/>).</summary>
[Collection(TimingCollection.Name)]
[Trait("Category", "Slow")]
public class WireTimeTests(ITestOutputHelper output)
{
    [Fact]
    public async Task A_131_character_frame_at_9600_7E2_takes_its_wire_time()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { BaudRate = 9600, BitsPerCharacter = 11 });
        string command = RawHost.Command("@00TS" + new string('W', 122));
        command.Length.Should().Be(131);
        double expectedMs = 131 * 11 * 1000.0 / 9600; // 150.1 ms

        var measured = new List<double>();
        for (int i = 0; i < 7; i++)
        {
            await host.SendAsync(command);
            (string frame, long first, long last) = await host.ReadFrameTimedAsync();
            frame.Should().Be(command, "TS echoes the text");
            measured.Add(Stopwatch.GetElapsedTime(first, last).TotalMilliseconds);
        }

        // The median of seven: a busy machine can hold either end back now and then (the pacer before the last byte, the
        // receiver before it takes the first), so a few frames measure long or short.
        measured.Sort();
        double median = measured[measured.Count / 2];
        string all = string.Join(" / ", measured.Select(m => m.ToString("F2", System.Globalization.CultureInfo.InvariantCulture)));
        output.WriteLine($"131 chars at 9600 bps x 11 bits: expected {expectedMs:F2} ms, measured {all} ms, median {median:F2} ms");
        // Never faster than the line (2 %: a UART's clock); slower only by what a loaded machine holds a thread back. The
        // pacer's schedule itself is checked exactly on a fake clock (WirePacerScheduleTests).
        median.Should().BeGreaterThanOrEqualTo(expectedMs * 0.98, $"first-to-last byte of 131 characters at 9600 bps, 11 bits cannot be faster than the line (all: {all} ms)");
        median.Should().BeLessThan(expectedMs * 1.5, $"the pacer keeps the line's time, less what a busy machine delays it by (all: {all} ms)");
    }

    [Fact]
    public async Task Turnaround_delays_the_start_of_the_answer()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Turnaround = TimeSpan.FromMilliseconds(120) });
        long sent = Stopwatch.GetTimestamp();
        await host.SendAsync(RawHost.Command("@00MS"));
        (string _, long first, long _) = await host.ReadFrameTimedAsync();
        Stopwatch.GetElapsedTime(sent, first).Should().BeGreaterThanOrEqualTo(TimeSpan.FromMilliseconds(115));
    }

    [Fact]
    public async Task No_answer_starts_before_the_turnaround_however_the_timer_is_rounded()
    {
        // A timer is due by the coarse system tick and can fire a few milliseconds early; the turnaround must not.
        var turnaround = TimeSpan.FromMilliseconds(9);
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Turnaround = turnaround });
        var early = new List<double>();
        for (int i = 0; i < 400; i++)
        {
            long sent = Stopwatch.GetTimestamp();
            await host.SendAsync(RawHost.Command("@00MS"));
            (string _, long first, long _) = await host.ReadFrameTimedAsync();
            TimeSpan waited = Stopwatch.GetElapsedTime(sent, first);
            if (waited < turnaround)
            {
                early.Add(waited.TotalMilliseconds);
            }
        }

        early.Should().BeEmpty("the simulator waits its whole turnaround before an answer (early answers, ms: {0})", string.Join(", ", early));
    }

    [Fact]
    public async Task Without_a_baud_rate_answers_are_not_paced()
    {
        await using RawHost host = RawHost.Start();
        string command = RawHost.Command("@00TS" + new string('W', 122));
        await host.SendAsync(command);
        (string _, long first, long last) = await host.ReadFrameTimedAsync();
        Stopwatch.GetElapsedTime(first, last).Should().BeLessThan(TimeSpan.FromMilliseconds(50));
    }
}
