using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The cycle a scan class can expect on a line it shares: each case worked out by hand from the schedule (classes
/// starting at their places' phases, each on a fixed schedule from there, reads taken whole and in the order asked).
/// </summary>
public sealed class LineScheduleTests
{
    private static LineSchedule.Watch Watch(int intervalMs, int reads, int readMs, int place = 0)
        => new(TimeSpan.FromMilliseconds(intervalMs), Enumerable.Repeat(TimeSpan.FromMilliseconds(readMs), reads).ToArray(), LineSchedule.Phase(place));

    [Fact]
    public void A_class_alone_on_its_line_expects_its_own_time_on_the_line()
    {
        LineSchedule.ExpectedCycles([Watch(100, 3, 10)]).Should().Equal(TimeSpan.FromMilliseconds(30));
        LineSchedule.ExpectedCycles([Watch(100, 3, 50)]).Should().Equal(TimeSpan.FromMilliseconds(150));
    }

    [Fact]
    public void Classes_come_due_in_their_order_every_cycle_and_wait_for_the_ones_before()
    {
        // Two units' 30 ms reads every 100 ms, the second starting 10 ms after the first: the first reads at once
        // (30 ms), the second waits 20 ms for it (50 ms), every cycle the same way.
        LineSchedule.Phase(1).Should().Be(TimeSpan.FromMilliseconds(10));
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 30, place: 0), Watch(100, 1, 30, place: 1)]);

        cycles.Should().Equal(TimeSpan.FromMilliseconds(30), TimeSpan.FromMilliseconds(50));
    }

    [Fact]
    public void A_slow_class_stretches_by_the_reads_of_a_fast_class_that_come_between_its_own()
    {
        // 100 reads of 10 ms every 10 s, from 10 ms, beside one read of 10 ms every 100 ms: the fast class comes due
        // ten or eleven times during the slow class's reads and takes the line between two of them, so the slow class's
        // cycle is about 1.1 s; the fast class, due as a slow read ends, waits for the one the slow class asked for first
        // (10 ms) in those cycles of a hundred.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 10, place: 0), Watch(10_000, 100, 10, place: 1)]);

        cycles[1].TotalMilliseconds.Should().BeInRange(1090, 1120);
        cycles[0].TotalMilliseconds.Should().BeInRange(10, 11.5);
    }

    [Fact]
    public void Classes_that_together_need_more_than_the_line_each_expect_a_cycle_longer_than_their_interval()
    {
        // Two 80 ms reads every 100 ms: a round of the line takes 160 ms, and each class reads once a round; each
        // cycle starts late, at once, so it waits for the other's read (80 ms) before its own.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 80, place: 0), Watch(100, 1, 80, place: 1)]);

        cycles.Should().OnlyContain(c => c.TotalMilliseconds > 150 && c.TotalMilliseconds <= 160);
    }

    [Fact]
    public void Classes_with_nothing_to_read_or_none_at_all_are_answered()
    {
        LineSchedule.ExpectedCycles([]).Should().BeEmpty();
        LineSchedule.ExpectedCycles([Watch(100, 0, 10), Watch(1000, 2, 10)]).Should().Equal(TimeSpan.Zero, TimeSpan.FromMilliseconds(20));
    }
}
