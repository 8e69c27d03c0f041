using System.Net;
using OmronHostLink.Link;
using OmronHostLink.Planning;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Simulator;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;
using static OmronHostLink.Tests.Infrastructure.WatchSteps;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// WatchAsync against the simulator on a fake clock that moves only when the watch waits on it, so every cycle is one
/// deliberate step: changes once each, one planned read a cycle, outages and resumption, overruns, back-to-back polling.
/// </summary>
public sealed class WatchTests
{
    private static readonly TimeSpan Second = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);

    private static PlcTag[] Tags() => new[] { PlcTag.Parse("D100"), PlcTag.Parse("D102:float"), PlcTag.Parse("D104.03") };

    [Fact]
    public async Task Every_tag_is_reported_first_then_each_change_exactly_once_with_one_planned_read_a_cycle()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        PlcTag[] tags = Tags();
        new ReadPlanner().Plan(tags).TransactionCount.Should().Be(1, "the tags lie within a few words of each other");
        line.Plc.WriteWord(PlcArea.Dm, 100, 5);
        using var stop = new CancellationTokenSource();
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(tags, new WatchOptions { Interval = Second, TimeProvider = clock }, stop.Token)
            .GetAsyncEnumerator();

        WatchEvent[] initial = { await Next(watch), await Next(watch), await Next(watch) };
        initial.Should().OnlyContain(e => e.Kind == WatchEventKind.Changed && e.IsInitial && e.OldValue == null);
        initial.Select(e => e.Tag).Should().Equal(tags);
        initial.Select(e => e.TagIndex).Should().Equal(0, 1, 2);
        initial.Select(e => e.NewValue).Should().Equal(PlcValue.FromWord(5), PlcValue.FromSingle(0f), PlcValue.FromBit(false));
        initial[0].Timestamp.Should().Be(clock.GetUtcNow());
        line.FramesSent.Should().Be(1);

        // Cycle 2 sees D100 change; cycles 3-5 see nothing new; cycle 6 sees D102 change.
        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.WriteWord(PlcArea.Dm, 100, 6);
        clock.Advance(Second);
        WatchEvent change = await Completed(pending, watch);
        change.Kind.Should().Be(WatchEventKind.Changed);
        change.Tag.Should().BeSameAs(tags[0]);
        change.OldValue.Should().Be(PlcValue.FromWord(5));
        change.NewValue.Should().Be(PlcValue.FromWord(6));
        change.Timestamp.Should().Be(clock.GetUtcNow());

        pending = watch.MoveNextAsync();
        for (int cycle = 3; cycle <= 5; cycle++)
        {
            await clock.StepAsync(Second);
        }

        await clock.NextTimerAsync();
        pending.IsCompleted.Should().BeFalse("cycles 3-5 read the same values as cycle 2");
        line.FramesSent.Should().Be(5, "each cycle is one planned read of one transaction");
        line.Plc.WriteWords(PlcArea.Dm, 102, new ushort[] { 0x0000, 0x3FC0 }); // 1.5f, low word first
        clock.Advance(Second);
        change = await Completed(pending, watch);
        change.Tag.Should().BeSameAs(tags[1]);
        change.OldValue.Should().Be(PlcValue.FromSingle(0f));
        change.NewValue.Should().Be(PlcValue.FromSingle(1.5f));

        // A bit elsewhere in the watched word changes the word but not the tag; the tag's bit then changes once.
        pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.SetBit(PlcArea.Dm, 104, 7, true);
        clock.Advance(Second);
        await clock.NextTimerAsync();
        pending.IsCompleted.Should().BeFalse("D104.07 is not watched");
        line.Plc.SetBit(PlcArea.Dm, 104, 3, true);
        clock.Advance(Second);
        change = await Completed(pending, watch);
        change.Tag.Should().BeSameAs(tags[2]);
        change.NewValue.ToBoolean().Should().BeTrue();
        line.FramesSent.Should().Be(8);
    }

    [Fact]
    public async Task A_change_carries_the_words_its_value_was_decoded_from()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        line.Plc.WriteWords(PlcArea.Dm, 102, new ushort[] { 0x0000, 0x3FC0 }); // 1.5f, low word first
        line.Plc.WriteWord(PlcArea.Dm, 104, 0x0088);
        line.Plc.SetFlag(PlcArea.Timer, 5, true);
        PlcTag[] tags = [PlcTag.Parse("D102:float"), PlcTag.Parse("D104.03"), PlcTag.Parse("T5:bit")];
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(tags, new WatchOptions { Interval = Second, TimeProvider = clock })
            .GetAsyncEnumerator();

        WatchEvent real = await Next(watch);
        real.NewValue.Should().Be(PlcValue.FromSingle(1.5f));
        real.Words.Should().Equal(0x0000, 0x3FC0);
        WatchEvent bit = await Next(watch);
        bit.NewValue.Should().Be(PlcValue.FromBit(true));
        bit.Words.Should().Equal(new ushort[] { 0x0088 }, "a bit carries the word that holds it");
        (await Next(watch)).Words.Should().Equal(new ushort[] { 1 }, "a completion flag is read as a word 0 or 1");

        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.WriteWords(PlcArea.Dm, 102, new ushort[] { 0x0000, 0x4020 }); // 2.5f
        clock.Advance(Second);
        WatchEvent change = await Completed(pending, watch);
        change.Words.Should().Equal(0x0000, 0x4020);
        WatchEvent.Polled(TimeSpan.Zero, clock.GetUtcNow()).Words.Should().BeEmpty();
        WatchEvent.Changed(0, tags[0], null, PlcValue.FromSingle(1f), clock.GetUtcNow()).Words.Should().BeEmpty();
    }

    [Fact]
    public async Task An_outage_is_reported_once_then_resumption_and_the_changes_it_hid_and_the_stream_goes_on()
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 100, 1);
        var host = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, 0));
        await host.StartAsync();
        int port = host.EndPoint.Port;
        await using HostLinkClient client = HostLinkClient.ForTcp("127.0.0.1", port, new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = Allowances.LosslessLine,
        }, connectTimeout: TimeSpan.FromSeconds(2));
        var clock = new SteppingClock();
        var retry = TimeSpan.FromSeconds(5);
        using var stop = new CancellationTokenSource();
        await using IAsyncEnumerator<WatchEvent> watch = client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, RetryInterval = retry, TimeProvider = clock }, stop.Token)
            .GetAsyncEnumerator();
        try
        {
            (await Next(watch)).NewValue.Should().Be(PlcValue.FromWord(1));

            ValueTask<bool> pending = watch.MoveNextAsync();
            await clock.NextTimerAsync();
            await host.StopAsync();
            clock.Advance(Second);
            WatchEvent outage = await Completed(pending, watch);
            outage.Kind.Should().Be(WatchEventKind.Outage);
            outage.Exception.Should().BeAssignableTo<HostLinkException>().Which.IsTransient.Should().BeTrue();
            DateTimeOffset outageAt = outage.Timestamp;

            // A second failed try is not reported again.
            pending = watch.MoveNextAsync();
            await clock.StepAsync(retry);
            await clock.NextTimerAsync();
            pending.IsCompleted.Should().BeFalse("the outage was reported when it began");

            plc.WriteWord(PlcArea.Dm, 100, 2);
            host = new TcpSimulatorHost(plc, new IPEndPoint(IPAddress.Loopback, port));
            await host.StartAsync();
            clock.Advance(retry);
            WatchEvent resumed = await Completed(pending, watch);
            resumed.Kind.Should().Be(WatchEventKind.Resumed);
            resumed.Duration.Should().Be(retry + retry, "the outage began at the first failure and ended two retry intervals later");
            resumed.Timestamp.Should().Be(outageAt + retry + retry);

            WatchEvent hidden = await Next(watch);
            hidden.Kind.Should().Be(WatchEventKind.Changed);
            hidden.OldValue.Should().Be(PlcValue.FromWord(1), "the last value reported before the outage");
            hidden.NewValue.Should().Be(PlcValue.FromWord(2));

            pending = watch.MoveNextAsync();
            await clock.NextTimerAsync();
            plc.WriteWord(PlcArea.Dm, 100, 3);
            clock.Advance(Second);
            (await Completed(pending, watch)).NewValue.Should().Be(PlcValue.FromWord(3));
        }
        finally
        {
            await host.DisposeAsync();
        }
    }

    [Fact]
    public async Task A_value_that_does_not_decode_is_an_outage_not_an_end()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x00A1);
        var clock = new SteppingClock();
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D200:bcd") }, new WatchOptions { Interval = Second, RetryInterval = Second, TimeProvider = clock })
            .GetAsyncEnumerator();

        WatchEvent outage = await Next(watch);
        outage.Kind.Should().Be(WatchEventKind.Outage);
        outage.Exception.Should().BeOfType<FormatException>().Which.Message.Should().Contain("0x00A1 is not BCD");

        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x0421);
        clock.Advance(Second);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Resumed);
        WatchEvent first = await Next(watch);
        first.IsInitial.Should().BeTrue();
        first.NewValue.Should().Be(PlcValue.FromBcd(421));
    }

    /// <summary>Returns what makes the next command sent take <paramref name="by"/> on the clock.</summary>
    private static Action SlowNextSend(InProcessLine line, SteppingClock clock, TimeSpan by)
    {
        bool slow = false;
        line.OnSend = () =>
        {
            if (slow)
            {
                slow = false;
                clock.Advance(by);
            }
        };
        return () => slow = true;
    }

    [Fact]
    public async Task A_cycle_longer_than_the_interval_is_an_overrun_and_the_next_starts_at_once_without_a_backlog()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        Action slowNextSend = SlowNextSend(line, clock, TimeSpan.FromSeconds(3.3));
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, TimeProvider = clock })
            .GetAsyncEnumerator();
        (await Next(watch)).IsInitial.Should().BeTrue();

        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        slowNextSend();
        clock.Advance(Second);
        WatchEvent overrun = await Completed(pending, watch);
        overrun.Kind.Should().Be(WatchEventKind.Overrun);
        overrun.Duration.Should().Be(TimeSpan.FromSeconds(3.3));
        line.FramesSent.Should().Be(2);
        int timers = clock.TimersCreated;

        // The next cycle runs at once (at 4.3 s, in the place of the one due at 4 s, the nearest); the one after is due
        // on the schedule, at 5 s: 3 missed cycles are not made up.
        pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.FramesSent.Should().Be(3);
        clock.TimersCreated.Should().Be(timers + 1);
        clock.LastDueTime.Should().Be(TimeSpan.FromSeconds(0.7), "the schedule goes on from where it was: cycles at whole seconds");
        pending.IsCompleted.Should().BeFalse();
        line.Plc.WriteWord(PlcArea.Dm, 100, 9);
        clock.Advance(TimeSpan.FromSeconds(0.7));
        (await Completed(pending, watch)).NewValue.Should().Be(PlcValue.FromWord(9));
        line.FramesSent.Should().Be(4);
    }

    [Fact]
    public async Task A_long_cycle_is_followed_by_one_overrun_not_by_cycles_back_to_back()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        Action slowNextSend = SlowNextSend(line, clock, TimeSpan.FromSeconds(3.8));
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, TimeProvider = clock, ReportEveryCycle = true })
            .GetAsyncEnumerator();
        (await Next(watch)).IsInitial.Should().BeTrue();
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);

        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        slowNextSend();
        clock.Advance(Second);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Polled);

        // The cycle due at 1 s ended at 4.8 s: the next runs at once in the place of the one due at 5 s (the nearest),
        // so the one after it is due at 6 s, a whole interval on — not at 5 s, right behind it.
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Overrun);
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);
        line.FramesSent.Should().Be(3);
        await NextCycleAsync(watch, clock, TimeSpan.FromSeconds(1.2), "the one after it is due at 6 s");
        line.FramesSent.Should().Be(4);
    }

    /// <summary>The next event is a cycle the watch waits for, <paramref name="due"/> on by the clock (to a millisecond), and it polls.</summary>
    private static async Task NextCycleAsync(IAsyncEnumerator<WatchEvent> watch, SteppingClock clock, TimeSpan due, string because)
    {
        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        pending.IsCompleted.Should().BeFalse(because);
        clock.LastDueTime.Should().BeCloseTo(due, TimeSpan.FromMilliseconds(1), because);
        clock.Advance(clock.LastDueTime);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Polled);
    }

    [Fact]
    public async Task Cycles_keep_their_schedule_when_timers_wake_late_or_early()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        TimeSpan late = TimeSpan.FromMilliseconds(15);
        TimeSpan early = TimeSpan.FromMilliseconds(0.9);
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, TimeProvider = clock, ReportEveryCycle = true })
            .GetAsyncEnumerator();
        (await Next(watch)).IsInitial.Should().BeTrue();
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);

        // Each wake comes 15 ms late: the next cycle is still due on the whole second, not an interval after this one began.
        for (int cycle = 1; cycle <= 5; cycle++)
        {
            ValueTask<bool> polled = watch.MoveNextAsync();
            await clock.NextTimerAsync();
            clock.LastDueTime.Should().Be(cycle == 1 ? Second : Second - late, "cycle {0} is due at {0} s", cycle);
            clock.Advance(clock.LastDueTime + late);
            (await Completed(polled, watch)).Kind.Should().Be(WatchEventKind.Polled);
        }

        line.FramesSent.Should().Be(6);

        // A wake just before its time by the timestamps: that cycle runs once, and the next is due a whole interval on.
        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        clock.LastDueTime.Should().Be(Second - late);
        clock.TimestampLag = early;
        clock.Advance(clock.LastDueTime);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Polled);
        line.FramesSent.Should().Be(7, "the cycle due at 6 s ran once");
        await NextCycleAsync(watch, clock, Second + early, "the cycle after it is due at 7 s, not again at 6 s (a timer waits whole milliseconds)");
        line.FramesSent.Should().Be(8);
    }

    [Fact]
    public async Task A_schedule_anchored_before_the_watch_starts_keeps_its_phase()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        long anchor = clock.GetTimestamp() - (long)(2.3 * clock.TimestampFrequency);
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, TimeProvider = clock, ReportEveryCycle = true, ScheduleStart = anchor })
            .GetAsyncEnumerator();

        // Started 2.3 s after the anchor: the first cycle runs at once (no overrun), the next at 3 s after the anchor.
        (await Next(watch)).IsInitial.Should().BeTrue();
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);
        clock.TimersCreated.Should().Be(0);
        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        clock.LastDueTime.Should().BeCloseTo(TimeSpan.FromSeconds(0.7), TimeSpan.FromMilliseconds(1));
        clock.Advance(clock.LastDueTime);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Polled);

        // Anchored ahead: the first cycle waits for it.
        await using IAsyncEnumerator<WatchEvent> later = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = Second, TimeProvider = clock, ScheduleStart = clock.GetTimestamp() + (clock.TimestampFrequency / 4) })
            .GetAsyncEnumerator();
        pending = later.MoveNextAsync();
        await clock.NextTimerAsync();
        clock.LastDueTime.Should().Be(TimeSpan.FromSeconds(0.25));
        pending.IsCompleted.Should().BeFalse();
        clock.Advance(clock.LastDueTime);
        (await Completed(pending, later)).IsInitial.Should().BeTrue();
    }

    [Fact]
    public async Task Interval_zero_polls_back_to_back_without_waiting_on_the_clock()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D100") }, new WatchOptions { Interval = TimeSpan.Zero, TimeProvider = clock })
            .GetAsyncEnumerator();
        (await Next(watch)).IsInitial.Should().BeTrue();

        ValueTask<bool> pending = watch.MoveNextAsync();
        await Eventually.UntilAsync(() => line.FramesSent >= 20, "the watch has polled 20 times without a change", patience: Patience);

        pending.IsCompleted.Should().BeFalse();
        line.Plc.WriteWord(PlcArea.Dm, 100, 1);
        WatchEvent change = await Completed(pending, watch);
        change.NewValue.Should().Be(PlcValue.FromWord(1));
        clock.TimersCreated.Should().Be(0);
    }

    [Fact]
    public async Task Cancelling_ends_the_loop_with_OperationCanceledException_and_leaving_the_loop_ends_it_quietly()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        var options = new WatchOptions { Interval = Second, TimeProvider = clock };
        using var stop = new CancellationTokenSource();
        var seen = new List<WatchEvent>();

        Func<Task> watching = async () =>
        {
            await foreach (WatchEvent e in line.Client.WatchAsync(new[] { PlcTag.Parse("D100") }, options, stop.Token))
            {
                seen.Add(e);
            }
        };
        Task run = watching();
        await clock.NextTimerAsync();
        stop.Cancel();
        await run.Awaiting(t => t).Should().ThrowAsync<OperationCanceledException>();
        seen.Should().ContainSingle().Which.IsInitial.Should().BeTrue();

        int framesBefore = line.FramesSent;
        await foreach (WatchEvent e in line.Client.WatchAsync(new[] { PlcTag.Parse("D100") }, options))
        {
            e.IsInitial.Should().BeTrue();
            break;
        }

        line.FramesSent.Should().Be(framesBefore + 1);
        (await line.Client.ReadAsync<ushort>("D100")).Should().Be(0, "the link is free after the watch ended");
    }

    [Fact]
    public async Task Retries_back_off_doubling_up_to_the_cap_and_every_cycle_is_reported_when_asked()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x00A1); // not BCD: every cycle fails at once, without timeouts
        var clock = new SteppingClock();
        var options = new WatchOptions { Interval = Second, RetryInterval = Second, MaxRetryInterval = TimeSpan.FromSeconds(4), ReportEveryCycle = true, TimeProvider = clock };
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(new[] { PlcTag.Parse("D200:bcd") }, options, CancellationToken.None)
            .GetAsyncEnumerator();

        WatchEvent outage = await Next(watch);
        outage.Kind.Should().Be(WatchEventKind.Outage);
        outage.RetryDelay.Should().Be(Second);

        // Each wait is exactly the delay announced: a tick less does not start the next try.
        TimeSpan waited = TimeSpan.Zero;
        TimeSpan delay = outage.RetryDelay;
        var announced = new List<TimeSpan>();
        for (int retry = 0; retry < 4; retry++)
        {
            ValueTask<bool> pending = watch.MoveNextAsync();
            await clock.NextTimerAsync();
            clock.Advance(delay - TimeSpan.FromTicks(1));
            pending.IsCompleted.Should().BeFalse($"retry {retry + 1} waits {delay}");
            clock.Advance(TimeSpan.FromTicks(1));
            WatchEvent failed = await Completed(pending, watch);
            failed.Kind.Should().Be(WatchEventKind.RetryFailed);
            failed.Exception.Should().BeOfType<FormatException>();
            waited += delay;
            delay = failed.RetryDelay;
            announced.Add(delay);
        }

        announced.Should().Equal(TimeSpan.FromSeconds(2), TimeSpan.FromSeconds(4), TimeSpan.FromSeconds(4), TimeSpan.FromSeconds(4));
        line.FramesSent.Should().Be(5);

        // Back: resumed, the value, then the cycle itself.
        ValueTask<bool> next = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x0421);
        clock.Advance(delay);
        WatchEvent resumed = await Completed(next, watch);
        resumed.Kind.Should().Be(WatchEventKind.Resumed);
        resumed.Duration.Should().Be(waited + delay);
        (await Next(watch)).NewValue.Should().Be(PlcValue.FromBcd(421));
        WatchEvent polled = await Next(watch);
        polled.Kind.Should().Be(WatchEventKind.Polled);
        polled.Timestamp.Should().Be(clock.GetUtcNow());

        // A cycle that changes nothing is still reported; the next outage starts again from the first delay.
        next = watch.MoveNextAsync();
        await clock.StepAsync(Second);
        (await Completed(next, watch)).Kind.Should().Be(WatchEventKind.Polled);
        next = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x00A1);
        clock.Advance(Second);
        WatchEvent again = await Completed(next, watch);
        again.Kind.Should().Be(WatchEventKind.Outage);
        again.RetryDelay.Should().Be(Second);
        again.ToString().Should().Contain("outage: ");
        WatchEvent.RetryFailed(again.Exception!, again.Timestamp, TimeSpan.FromSeconds(4)).ToString().Should().EndWith("; next try in 4 s");
    }

    [Fact]
    public async Task A_timer_completion_flag_is_watched_apart_from_its_present_value()
    {
        await using InProcessLine line = InProcessLine.Start();
        var clock = new SteppingClock();
        PlcTag[] tags = [PlcTag.Parse("T5:bit"), PlcTag.Parse("T5")];
        await using IAsyncEnumerator<WatchEvent> watch = line.Client
            .WatchAsync(tags, new WatchOptions { Interval = Second, TimeProvider = clock })
            .GetAsyncEnumerator();
        (await Next(watch)).NewValue.Should().Be(PlcValue.FromBit(false));
        (await Next(watch)).NewValue.Should().Be(PlcValue.FromWord(0));

        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        line.Plc.SetFlag(PlcArea.Timer, 5, true);
        clock.Advance(Second);
        WatchEvent change = await Completed(pending, watch);
        change.Tag.Should().BeSameAs(tags[0]);
        change.NewValue.Should().Be(PlcValue.FromBit(true));
        line.FramesSent.Should().Be(4, "each cycle reads the flag (RG) and the present value (RC)");
    }

    [Fact]
    public async Task A_cap_below_the_retry_interval_is_refused()
    {
        await using InProcessLine line = InProcessLine.Start();
        FluentActions.Invoking(() => line.Client.WatchAsync(new[] { PlcTag.Parse("D0") }, new WatchOptions { RetryInterval = TimeSpan.FromSeconds(5), MaxRetryInterval = TimeSpan.FromSeconds(2) }))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("MaxRetryInterval").WithMessage("*at least the retry interval (00:00:05)*");
        FluentActions.Invoking(() => line.Client.WatchAsync(new[] { PlcTag.Parse("D0") }, new WatchOptions { Interval = TimeSpan.FromSeconds(3), MaxRetryInterval = TimeSpan.FromSeconds(2) }))
            .Should().Throw<ArgumentOutOfRangeException>("the retry interval in force is the interval, 3 s");
        line.FramesSent.Should().Be(0);
    }

    [Fact]
    public async Task Bad_arguments_are_refused_by_the_call_before_anything_is_sent()
    {
        await using InProcessLine line = InProcessLine.Start();
        HostLinkUnit plc = line.Client;

        FluentActions.Invoking(() => plc.WatchAsync(Array.Empty<PlcTag>(), Second)).Should().Throw<ArgumentException>().WithMessage("*at least one tag*");
        FluentActions.Invoking(() => plc.WatchAsync(new[] { PlcTag.Parse("D0") }, TimeSpan.FromSeconds(-1))).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("interval");
        FluentActions.Invoking(() => plc.WatchAsync(new[] { PlcTag.Parse("D0") }, new WatchOptions { RetryInterval = TimeSpan.Zero })).Should().Throw<ArgumentOutOfRangeException>().WithParameterName("RetryInterval");
        FluentActions.Invoking(() => plc.WatchAsync(new[] { PlcTag.Parse("W0") }, Second)).Should().Throw<ArgumentException>("C-mode cannot read the work area");

        line.FramesSent.Should().Be(0);
    }
}
