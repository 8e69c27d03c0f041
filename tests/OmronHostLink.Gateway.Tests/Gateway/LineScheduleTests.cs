using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The cycle a scan class can expect on a line it shares: each case worked out by hand from the schedule (classes
/// starting at their places' phases, each on a fixed schedule from there, reads taken whole and in the order asked,
/// each read its time on the line and the host's hand-over).
/// </summary>
public sealed class LineScheduleTests
{
    private static readonly double H = LineSchedule.HandOver.TotalMilliseconds;

    private static LineSchedule.Watch Watch(int intervalMs, int reads, int readMs, int place = 0)
        => new(TimeSpan.FromMilliseconds(intervalMs), Enumerable.Repeat(TimeSpan.FromMilliseconds(readMs), reads).ToArray(), LineSchedule.Phase(place));

    [Fact]
    public void A_class_alone_on_its_line_expects_its_own_time_on_the_line_and_a_hand_over_a_read()
    {
        LineSchedule.HandOver.Should().BePositive();
        LineSchedule.ExpectedCycles([Watch(100, 3, 10)]).Should().Equal(Ms(30 + (3 * H)));
        LineSchedule.ExpectedCycles([Watch(100, 3, 50)]).Should().Equal(Ms(150 + (3 * H)));
    }

    [Fact]
    public void Classes_come_due_in_their_order_every_cycle_and_wait_for_the_ones_before()
    {
        // Two units' 30 ms reads every 100 ms, the second starting 10 ms after the first: the first reads at once
        // (30 ms and a hand-over), the second waits 20 ms and a hand-over for it, then reads, every cycle the same way.
        LineSchedule.Phase(1).Should().Be(TimeSpan.FromMilliseconds(10));
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 30, place: 0), Watch(100, 1, 30, place: 1)]);

        cycles.Should().Equal(Ms(30 + H), Ms(50 + (2 * H)));
    }

    [Fact]
    public void A_slow_class_stretches_by_the_reads_of_a_fast_class_that_come_between_its_own()
    {
        // 100 reads of 10 ms every 10 s, from 10 ms, beside one read of 10 ms every 100 ms (each read and its hand-over
        // 10 + H): the fast class comes due eleven or twelve times during the slow class's reads and takes the line
        // between two of them, so the slow class's cycle is 111 or 112 reads; the fast class, due as a slow read ends,
        // waits for the one the slow class asked for first in those cycles of a hundred.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 10, place: 0), Watch(10_000, 100, 10, place: 1)]);

        cycles[1].TotalMilliseconds.Should().BeInRange(111 * (10 + H), 112 * (10 + H));
        cycles[0].TotalMilliseconds.Should().BeInRange(10 + H, 11.5 + H);
    }

    [Fact]
    public void Classes_that_together_need_more_than_the_line_each_expect_a_cycle_longer_than_their_interval()
    {
        // Two 80 ms reads every 100 ms: a round of the line takes two reads and their hand-overs, and each class reads
        // once a round; each cycle starts late, at once, so it waits for the other's read before its own.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 80, place: 0), Watch(100, 1, 80, place: 1)]);

        cycles.Should().OnlyContain(c => c.TotalMilliseconds > 150 && c.TotalMilliseconds <= 160 + (2 * H));
    }

    [Fact]
    public void Classes_with_nothing_to_read_or_none_at_all_are_answered()
    {
        LineSchedule.ExpectedCycles([]).Should().BeEmpty();
        LineSchedule.ExpectedCycles([Watch(100, 0, 10), Watch(1000, 2, 10)]).Should().Equal(TimeSpan.Zero, Ms(20 + (2 * H)));
    }

    private static TimeSpan Ms(double ms) => TimeSpan.FromTicks((long)Math.Round(ms * TimeSpan.TicksPerMillisecond));
}
