using OmronHostLink.Planning;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Tests.Infrastructure;
using static OmronHostLink.Tests.Infrastructure.WatchSteps;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// WatchAsync's demotion (<see cref="WatchOptions.DemoteAfter"/>): a unit silent for that many cycles in a row is not
/// read for the demotion period, then one presence probe decides. The watch's waits run on a stepping clock; the
/// line's deadlines are real (a silent unit costs its turnaround allowance, generous here so that an answering unit is
/// never taken for a silent one on a loaded machine).
/// </summary>
public sealed class WatchDemotionTests
{
    private static readonly TimeSpan Second = TimeSpan.FromSeconds(1);
    private static readonly TimeSpan Period = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task A_unit_silent_for_DemoteAfter_cycles_is_demoted_left_alone_for_the_period_then_probed_once_and_read_when_it_answers()
    {
        var faults = new FaultOptions();
        await using InProcessLine line = InProcessLine.Start(
            new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromSeconds(2), ReadRetries = 0 },
            new VirtualPlcOptions { Faults = faults });
        line.Plc.WriteWord(PlcArea.Dm, 100, 7);
        var clock = new SteppingClock();
        var options = new WatchOptions { Interval = Second, RetryInterval = Second, DemoteAfter = 2, DemotionPeriod = Period, ReportEveryCycle = true, TimeProvider = clock };
        await using IAsyncEnumerator<WatchEvent> watch = line.Client.WatchAsync([PlcTag.Parse("D100")], options).GetAsyncEnumerator();
        (await Next(watch)).NewValue.Should().Be(PlcValue.FromWord(7));
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);

        // The unit falls silent: the first silent cycle is the outage, the second demotes it.
        faults.Drop = 1;
        ValueTask<bool> pending = watch.MoveNextAsync();
        await clock.StepAsync(Second);
        WatchEvent outage = await Completed(pending, watch);
        outage.Kind.Should().Be(WatchEventKind.Outage);
        outage.Exception.Should().BeOfType<HostLinkTimeoutException>();
        outage.RetryDelay.Should().Be(Second, "one silent cycle of two does not demote");
        pending = watch.MoveNextAsync();
        await clock.StepAsync(Second);
        WatchEvent demoted = await Completed(pending, watch);
        demoted.Kind.Should().Be(WatchEventKind.Demoted);
        demoted.Exception.Should().BeOfType<HostLinkTimeoutException>();
        demoted.RetryDelay.Should().Be(Period);
        demoted.ToString().Should().Contain("demoted: ").And.EndWith("; next probe in 10 s");

        // Nothing is sent for the whole period; then one probe (TS), and the unit stays demoted.
        int sent = line.FramesSent;
        pending = watch.MoveNextAsync();
        await clock.NextTimerAsync();
        // The watch waits on this clock's timer (armed, above): until it fires, nothing can be sent.
        clock.Advance(Period - TimeSpan.FromTicks(1));
        pending.IsCompleted.Should().BeFalse();
        line.FramesSent.Should().Be(sent, "a demoted unit is not read during its demotion period");
        clock.Advance(TimeSpan.FromTicks(1));
        WatchEvent stillSilent = await Completed(pending, watch);
        stillSilent.Kind.Should().Be(WatchEventKind.RetryFailed);
        stillSilent.Exception!.Message.Should().Contain("did not answer a presence probe (TS)").And.Contain("stays demoted");
        stillSilent.RetryDelay.Should().Be(Period);
        line.FramesSent.Should().Be(sent + 1, "the probe is one TS, never retried, and no read follows a silent probe");

        // The unit answers again: the next probe lets the read through, and the watch resumes.
        faults.Drop = 0;
        line.Plc.WriteWord(PlcArea.Dm, 100, 8);
        pending = watch.MoveNextAsync();
        await clock.StepAsync(Period);
        WatchEvent resumed = await Completed(pending, watch);
        resumed.Kind.Should().Be(WatchEventKind.Resumed);
        (await Next(watch)).NewValue.Should().Be(PlcValue.FromWord(8));
        (await Next(watch)).Kind.Should().Be(WatchEventKind.Polled);
        line.FramesSent.Should().Be(sent + 3, "a probe (TS), then the read (RD)");

        // Restored: the next silence starts the count again (one silent cycle is an outage, not a demotion).
        faults.Drop = 1;
        pending = watch.MoveNextAsync();
        await clock.StepAsync(Second);
        (await Completed(pending, watch)).Kind.Should().Be(WatchEventKind.Outage);
    }

    [Fact]
    public async Task After_a_silent_probe_the_next_request_fences_only_its_own_unit()
    {
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { TurnaroundAllowance = TimeSpan.FromSeconds(1) });
        line.Plc.WriteWord(PlcArea.Dm, 0, 42);

        (await line.Client.Unit(5).ProbeAsync()).Should().BeNull("nobody answers unit 5");
        (await line.Client.ReadWordAsync("D0")).Should().Be(42);

        line.FramesSent.Should().Be(3, "the probe, one fence at unit 0 and the read: the silent unit is not fenced again (its late echo would carry the probe's token)");
    }

    [Fact]
    public async Task A_unit_that_answers_with_an_error_is_not_demoted()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWord(PlcArea.Dm, 200, 0x00A1); // not BCD: every cycle fails, but the unit answers
        var clock = new SteppingClock();
        var options = new WatchOptions { Interval = Second, RetryInterval = Second, DemoteAfter = 1, ReportEveryCycle = true, TimeProvider = clock };
        await using IAsyncEnumerator<WatchEvent> watch = line.Client.WatchAsync([PlcTag.Parse("D200:bcd")], options).GetAsyncEnumerator();

        (await Next(watch)).Kind.Should().Be(WatchEventKind.Outage);
        for (int i = 0; i < 3; i++)
        {
            ValueTask<bool> pending = watch.MoveNextAsync();
            await clock.StepAsync(Second);
            WatchEvent e = await Completed(pending, watch);
            e.Kind.Should().Be(WatchEventKind.RetryFailed, "only silence demotes");
            e.RetryDelay.Should().Be(Second);
        }

        line.FramesSent.Should().Be(4, "every cycle reads; no probe");
    }

    [Fact]
    public async Task Demotion_settings_out_of_range_are_refused_before_anything_is_sent()
    {
        await using InProcessLine line = InProcessLine.Start();
        PlcTag[] tags = [PlcTag.Parse("D0")];
        FluentActions.Invoking(() => line.Client.WatchAsync(tags, new WatchOptions { DemoteAfter = -1 }))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("DemoteAfter").WithMessage("DemoteAfter must be 0 (never) up to 1000; it was -1.*");
        FluentActions.Invoking(() => line.Client.WatchAsync(tags, new WatchOptions { DemoteAfter = 1001 }))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("DemoteAfter");
        FluentActions.Invoking(() => line.Client.WatchAsync(tags, new WatchOptions { DemoteAfter = 3, DemotionPeriod = TimeSpan.Zero }))
            .Should().Throw<ArgumentOutOfRangeException>().WithParameterName("DemotionPeriod");
        line.FramesSent.Should().Be(0);
    }
}
