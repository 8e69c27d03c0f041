using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The cycle a scan class can expect on a line it shares: each case worked out by hand from the schedule (classes due
/// from a common start, reads taken whole and in the order asked).
/// </summary>
public sealed class LineScheduleTests
{
    private static LineSchedule.Watch Watch(int intervalMs, int reads, int readMs)
        => new(TimeSpan.FromMilliseconds(intervalMs), Enumerable.Repeat(TimeSpan.FromMilliseconds(readMs), reads).ToArray());

    [Fact]
    public void A_class_alone_on_its_line_expects_its_own_time_on_the_line()
    {
        LineSchedule.ExpectedCycles([Watch(100, 3, 10)]).Should().Equal(TimeSpan.FromMilliseconds(30));
        LineSchedule.ExpectedCycles([Watch(100, 3, 50)]).Should().Equal(TimeSpan.FromMilliseconds(150));
    }

    [Fact]
    public void Two_classes_due_together_wait_for_each_other_in_turn()
    {
        // Two units' 10 ms reads every 100 ms, due at the same instants: one reads at once (10 ms), the other after it
        // (20 ms), first one then the other, so each expects 15 ms.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 10), Watch(100, 1, 10)]);

        cycles.Should().HaveCount(2);
        cycles.Should().OnlyContain(c => c.TotalMilliseconds >= 14.5 && c.TotalMilliseconds <= 15.5);
    }

    [Fact]
    public void A_slow_class_stretches_by_the_reads_of_a_fast_class_that_come_between_its_own()
    {
        // 100 reads of 10 ms every 10 s beside one read of 10 ms every 100 ms: the fast class comes due eleven times
        // during the slow class's reads and takes the line between two of them, so the slow class's cycle is about
        // 1.1 s; the fast class waits for one slow read (10 ms) in those eleven cycles of a hundred.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 10), Watch(10_000, 100, 10)]);

        cycles[1].TotalMilliseconds.Should().BeInRange(1090, 1120);
        cycles[0].TotalMilliseconds.Should().BeInRange(10, 11.5);
    }

    [Fact]
    public void Classes_that_together_need_more_than_the_line_each_expect_a_cycle_longer_than_their_interval()
    {
        // Two 80 ms reads every 100 ms: a round of the line takes 160 ms, and each class reads once a round.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 80), Watch(100, 1, 80)]);

        cycles.Should().OnlyContain(c => c.TotalMilliseconds > 150 && c.TotalMilliseconds <= 160);
    }

    [Fact]
    public void Classes_with_nothing_to_read_or_none_at_all_are_answered()
    {
        LineSchedule.ExpectedCycles([]).Should().BeEmpty();
        LineSchedule.ExpectedCycles([Watch(100, 0, 10), Watch(1000, 2, 10)]).Should().Equal(TimeSpan.Zero, TimeSpan.FromMilliseconds(20));
    }
}
