using OmronHostLink.Worker.Polling;

namespace OmronHostLink.Tests.Worker;

public sealed class PollSchedulerTests
{
    private static TimeSpan Ms(double ms) => TimeSpan.FromMilliseconds(ms);

    [Fact]
    public void Everything_is_due_at_start_in_the_order_given()
    {
        var s = new PollScheduler<string>([("a", Ms(100)), ("b", Ms(10))], Ms(0));
        (int slot, TimeSpan at) = s.Next();
        s[slot].Should().Be("a");
        at.Should().Be(Ms(0));
        s.Completed(slot, Ms(1));
        s[s.Next().Slot].Should().Be("b");
    }

    [Fact]
    public void Earliest_due_runs_first_and_ties_go_to_the_least_recently_run()
    {
        var s = new PollScheduler<string>([("a", Ms(10)), ("b", Ms(10)), ("c", Ms(10))], Ms(0));
        var order = new List<string>();
        TimeSpan now = Ms(0);
        for (int i = 0; i < 9; i++)
        {
            (int slot, TimeSpan at) = s.Next();
            now = at > now ? at : now;
            order.Add(s[slot]);
            s.Completed(slot, now);
        }

        order.Should().Equal("a", "b", "c", "a", "b", "c", "a", "b", "c");
    }

    [Fact]
    public void No_group_starves_on_an_overloaded_link()
    {
        // Three groups want a poll every 10 ms, each poll takes 25 ms (and one of them 60 ms): the link can never keep up.
        var s = new PollScheduler<string>([("fast", Ms(10)), ("also-fast", Ms(10)), ("slow-read", Ms(10)), ("rare", Ms(500))], Ms(0));
        var counts = new Dictionary<string, int>();
        TimeSpan now = Ms(0);
        for (int i = 0; i < 1000; i++)
        {
            (int slot, TimeSpan at) = s.Next();
            now = (at > now ? at : now) + (s[slot] == "slow-read" ? Ms(60) : Ms(25));
            counts[s[slot]] = counts.GetValueOrDefault(s[slot]) + 1;
            s.Completed(slot, now);
        }

        counts["fast"].Should().BeCloseTo(counts["also-fast"], 1);
        counts["slow-read"].Should().BeCloseTo(counts["fast"], 1);
        // The rare group still gets its turn every time it is due.
        counts["rare"].Should().BeGreaterThanOrEqualTo((int)(now.TotalMilliseconds / 500) - 1);
    }

    [Fact]
    public void Missed_ticks_are_skipped_not_queued()
    {
        var s = new PollScheduler<string>([("a", Ms(10))], Ms(0));
        (int slot, _) = s.Next();
        long skipped = s.Completed(slot, Ms(35));
        skipped.Should().Be(3);
        s.DueAt(slot).Should().Be(Ms(40), "the group keeps its phase and runs at the next tick after now");
        s.Completed(slot, Ms(41)).Should().Be(0);
        s.DueAt(slot).Should().Be(Ms(50));
    }

    [Fact]
    public void A_held_back_item_lets_the_others_run()
    {
        var s = new PollScheduler<string>([("down", Ms(10)), ("up", Ms(10))], Ms(0));
        (int slot, TimeSpan at) = s.Next(item => item == "down" ? Ms(1000) : TimeSpan.Zero);
        s[slot].Should().Be("up");
        at.Should().Be(Ms(0));
        s.Completed(slot, Ms(1));
        (slot, at) = s.Next(item => item == "down" ? Ms(1000) : TimeSpan.Zero);
        s[slot].Should().Be("up");
        at.Should().Be(Ms(10));
    }
}
