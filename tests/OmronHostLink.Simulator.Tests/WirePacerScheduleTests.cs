using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Simulator.Tests;

/// <summary>The simulator's wire-time schedule, without a clock: which byte is handed over when.</summary>
public sealed class WirePacerScheduleTests
{
    private static readonly WirePacer At9600 = new(9600, 11);

    [Fact]
    public void A_131_character_frame_at_9600_7E2_spans_its_wire_time_first_byte_to_last()
    {
        double expectedMs = 131 * 11 * 1000.0 / 9600; // 150.1 ms

        At9600.DueTime(0, 131).Should().Be(TimeSpan.Zero);
        At9600.DueTime(130, 131).TotalMilliseconds.Should().BeApproximately(expectedMs, 0.001);
        At9600.WireTime(131).TotalMilliseconds.Should().BeApproximately(expectedMs, 0.001);
    }

    [Fact]
    public void Bytes_between_are_spread_evenly()
    {
        double step = At9600.DueTime(1, 131).TotalMilliseconds;
        for (int i = 1; i < 131; i++)
        {
            (At9600.DueTime(i, 131) - At9600.DueTime(i - 1, 131)).TotalMilliseconds.Should().BeApproximately(step, 0.001);
        }
    }

    [Fact]
    public void The_count_due_follows_the_schedule()
    {
        At9600.DueCount(TimeSpan.Zero, 131).Should().Be(1, "the first byte goes at once");
        At9600.DueCount(At9600.DueTime(130, 131) - TimeSpan.FromMilliseconds(0.1), 131).Should().Be(130, "the last byte waits for its stop bit");
        At9600.DueCount(At9600.DueTime(130, 131), 131).Should().Be(131);
        At9600.DueCount(TimeSpan.FromSeconds(10), 131).Should().Be(131);
        for (int i = 0; i < 131; i++)
        {
            At9600.DueCount(At9600.DueTime(i, 131), 131).Should().Be(i + 1);
        }
    }

    [Fact]
    public void Without_a_baud_rate_nothing_is_paced()
    {
        var unpaced = new WirePacer(0, 11);

        unpaced.Enabled.Should().BeFalse();
        unpaced.WireTime(131).Should().Be(TimeSpan.Zero);
    }
}
