using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The cycle a scan class can expect on a line it shares: each case worked out by hand from the schedule (every class
/// reading at once at the start, then on a fixed schedule from its phase, reads taken whole and in the order asked,
/// each read its time on the line and the host's hand-over; cycles begun within the first longest interval left out).
/// </summary>
public sealed class LineScheduleTests
{
    private static readonly double H = LineSchedule.HandOver.TotalMilliseconds;

    private static LineSchedule.Watch Watch(int intervalMs, int reads, int readMs, double startMs = 0)
        => new(TimeSpan.FromMilliseconds(intervalMs), Enumerable.Repeat(TimeSpan.FromMilliseconds(readMs), reads).ToArray(), Ms(startMs));

    [Fact]
    public void Classes_of_one_interval_are_spread_across_it_and_no_two_classes_come_due_within_the_stagger()
    {
        // Worked by hand: each class from its spread place, a millisecond at a time, until it is 10 ms from every class
        // before it on the cycles they share (100 ms with a 100 ms class, 1 s between 1 s and 10 s classes).
        TimeSpan[] intervals = [Ms(100), Ms(1000), Ms(10_000), Ms(100), Ms(1000), Ms(10_000)];
        LineSchedule.Stagger.Should().Be(Ms(10));

        LineSchedule.Phases(intervals).Should().Equal(Ms(0), Ms(10), Ms(20), Ms(50), Ms(510), Ms(5020));
        LineSchedule.Phases([Ms(1000), Ms(1000), Ms(1000)]).Should().Equal(Ms(0), Ms(333.3333), Ms(666.6666));
        LineSchedule.Phases([Ms(100), Ms(250)]).Should().Equal(Ms(0), Ms(10));
    }

    [Fact]
    public void Where_no_place_is_a_stagger_from_all_the_farthest_is_taken()
    {
        // Eleven classes every 20 ms: no two can be 10 ms apart; each takes the place farthest from those before it.
        TimeSpan[] phases = LineSchedule.Phases(Enumerable.Repeat(Ms(20), 11).ToArray());

        // The second from its spread place (20 / 11 ms) in whole milliseconds: 9.82 ms, the farthest from the first.
        phases[1].Should().Be(TimeSpan.FromTicks(Ms(20).Ticks / 11) + Ms(8));
        phases.Should().OnlyHaveUniqueItems();
    }

    [Fact]
    public void A_class_reads_at_once_and_then_on_its_phase()
    {
        // The anchor given to the watch: the latest of its scheduled times at or before the start.
        LineSchedule.Anchor(Ms(540), Ms(1000)).Should().Be(Ms(-460));
        LineSchedule.Anchor(Ms(150), Ms(100)).Should().Be(Ms(-50));
        LineSchedule.Anchor(Ms(100), Ms(100)).Should().Be(Ms(0));
        LineSchedule.Anchor(TimeSpan.Zero, Ms(1000)).Should().Be(TimeSpan.Zero);
    }

    [Fact]
    public void Classes_of_one_interval_spread_across_it_do_not_wait_for_each_other()
    {
        // Two units' 65 ms reads every second: half a second apart, each has the line to itself.
        TimeSpan[] phases = LineSchedule.Phases([Ms(1000), Ms(1000)]);
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(1000, 1, 65, phases[0].TotalMilliseconds), Watch(1000, 1, 65, phases[1].TotalMilliseconds)]);

        cycles.Should().Equal(Ms(65 + H), Ms(65 + H));
    }

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
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 30, startMs: 0), Watch(100, 1, 30, startMs: 10)]);

        cycles.Should().Equal(Ms(30 + H), Ms(50 + (2 * H)));
    }

    [Fact]
    public void A_slow_class_stretches_by_the_reads_of_a_fast_class_that_come_between_its_own()
    {
        // 100 reads of 10 ms every 10 s, from 10 ms, beside one read of 10 ms every 100 ms (each read and its hand-over
        // 10 + H): the fast class comes due eleven or twelve times during the slow class's reads and takes the line
        // between two of them, so the slow class's cycle is 111 or 112 reads; the fast class, due as a slow read ends,
        // waits for the one the slow class asked for first in those cycles of a hundred.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 10, startMs: 0), Watch(10_000, 100, 10, startMs: 10)]);

        cycles[1].TotalMilliseconds.Should().BeInRange(111 * (10 + H), 113 * (10 + H));
        cycles[0].TotalMilliseconds.Should().BeInRange(10 + H, 11.5 + H);
    }

    [Fact]
    public void Classes_that_together_need_more_than_the_line_each_expect_a_cycle_longer_than_their_interval()
    {
        // Two 80 ms reads every 100 ms: a round of the line takes two reads and their hand-overs, and each class reads
        // once a round; each cycle starts late, at once, so it waits for the other's read before its own.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(100, 1, 80, startMs: 0), Watch(100, 1, 80, startMs: 10)]);

        cycles.Should().OnlyContain(c => c.TotalMilliseconds > 150 && c.TotalMilliseconds <= 160 + (2 * H));
    }

    [Fact]
    public void A_class_of_a_day_beside_one_of_milliseconds_is_answered_from_the_reads_run()
    {
        // Saturated 5 ms reads every millisecond beside one 5 ms read a day: the run stops at its read limit, and the
        // day's class, which has read only at the start, expects that cycle: its read behind one of the other class's.
        TimeSpan[] cycles = LineSchedule.ExpectedCycles([Watch(1, 1, 5, startMs: 0), new LineSchedule.Watch(TimeSpan.FromDays(1), [Ms(5)], Ms(10))]);

        cycles[1].Should().Be(Ms(10 + (2 * H)));
        cycles[0].TotalMilliseconds.Should().BeInRange(5 + H, 10 + (2 * H));
    }

    [Fact]
    public void Classes_with_nothing_to_read_or_none_at_all_are_answered()
    {
        LineSchedule.ExpectedCycles([]).Should().BeEmpty();
        LineSchedule.ExpectedCycles([Watch(100, 0, 10), Watch(1000, 2, 10)]).Should().Equal(TimeSpan.Zero, Ms(20 + (2 * H)));
    }

    private static TimeSpan Ms(double ms) => TimeSpan.FromTicks((long)Math.Round(ms * TimeSpan.TicksPerMillisecond));
}
