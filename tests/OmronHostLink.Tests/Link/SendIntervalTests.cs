using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>
/// The send interval: the next command waits until the gap since the end of the last exchange is the longer of the
/// link's and its unit's. On a fake clock that reports the timers the link arms: a command is "not yet" sent once the
/// link is waiting on the clock for exactly the gap, and nothing can move until the test advances the clock.
/// </summary>
public sealed class SendIntervalTests
{
    private static readonly TimeSpan Allowance = TimeSpan.FromMilliseconds(150);

    private static Task OffContext(Func<Task> test) => Task.Run(test);

    private static (HostLinkClient Client, ScriptedPlc Plc, TimerRecordingTimeProvider Time) Line(TimeSpan sendInterval, Dictionary<int, TimeSpan>? units = null)
    {
        var time = new TimerRecordingTimeProvider();
        (Stream host, Stream plc) = InMemoryLink.CreatePair();
        var options = new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = Allowance,
            SendInterval = sendInterval,
            TimeProvider = time,
        };
        foreach (KeyValuePair<int, TimeSpan> unit in units ?? [])
        {
            options.UnitSendIntervals[unit.Key] = unit.Value;
        }

        // The scripted PLC echoes every TS (TEST) frame: the probes below are answered at once.
        return (HostLinkClient.ForStream(host, options), new ScriptedPlc(plc, _ => null), time);
    }

    private static async Task WaitForFrames(ScriptedPlc plc, int count)
    {
        await Eventually.UntilAsync(() => plc.Received.Count >= count, $"the PLC has received {count} frames");
        plc.Received.Count.Should().Be(count);
    }

    /// <summary>Starts a probe and waits until the link waits on the clock before sending it; returns the wait armed.</summary>
    private static async Task<(Task<TimeSpan?> Probe, TimeSpan Wait)> ProbeWaitingAsync(HostLinkUnit unit, TimerRecordingTimeProvider time)
    {
        int armed = time.Armed.Count;
        Task<TimeSpan?> probe = unit.ProbeAsync();
        await time.ArmedAsync(armed + 1);
        return (probe, time.Armed[armed]);
    }

    [Fact]
    public Task The_next_command_waits_for_the_link_send_interval() => OffContext(async () =>
    {
        var (client, plc, time) = Line(TimeSpan.FromMilliseconds(40));
        await using var _ = plc;
        await using var __ = client;

        (await client.ProbeAsync()).Should().NotBeNull("the first command has no exchange before it to keep a gap from");
        await WaitForFrames(plc, 1);

        (Task<TimeSpan?> second, TimeSpan wait) = await ProbeWaitingAsync(client, time);
        wait.Should().Be(TimeSpan.FromMilliseconds(40), "the first timer the link arms is the whole gap, before anything is sent");
        plc.Received.Count.Should().Be(1, "the link waits on the clock for the gap since the first exchange ended");

        time.Advance(TimeSpan.FromMilliseconds(39));
        plc.Received.Count.Should().Be(1, "39 ms is still short of the interval");

        time.Advance(TimeSpan.FromMilliseconds(1));
        await WaitForFrames(plc, 2);
        (await second).Should().NotBeNull();
    });

    [Fact]
    public Task A_unit_with_a_longer_interval_waits_longer_and_others_keep_the_link_interval() => OffContext(async () =>
    {
        var (client, plc, time) = Line(TimeSpan.FromMilliseconds(10), new Dictionary<int, TimeSpan> { [3] = TimeSpan.FromMilliseconds(50) });
        await using var _ = plc;
        await using var __ = client;

        (await client.ProbeAsync()).Should().NotBeNull();
        await WaitForFrames(plc, 1);

        (Task<TimeSpan?> toUnit3, TimeSpan wait3) = await ProbeWaitingAsync(client.Unit(3), time);
        wait3.Should().Be(TimeSpan.FromMilliseconds(50), "unit 3 needs 50 ms after the last exchange");
        time.Advance(TimeSpan.FromMilliseconds(49));
        plc.Received.Count.Should().Be(1, "unit 3 needs 50 ms after the last exchange");
        time.Advance(TimeSpan.FromMilliseconds(1));
        await WaitForFrames(plc, 2);
        (await toUnit3).Should().NotBeNull();

        (Task<TimeSpan?> toUnit0, TimeSpan wait0) = await ProbeWaitingAsync(client, time);
        wait0.Should().Be(TimeSpan.FromMilliseconds(10), "unit 0 keeps the link's 10 ms");
        time.Advance(TimeSpan.FromMilliseconds(9));
        plc.Received.Count.Should().Be(2, "unit 0 keeps the link's 10 ms");
        time.Advance(TimeSpan.FromMilliseconds(1));
        await WaitForFrames(plc, 3);
        (await toUnit0).Should().NotBeNull();
    });

    [Fact]
    public Task Without_a_send_interval_commands_follow_at_once() => OffContext(async () =>
    {
        var (client, plc, _) = Line(TimeSpan.Zero);
        await using var __ = plc;
        await using var ___ = client;

        (await client.ProbeAsync()).Should().NotBeNull();
        (await client.ProbeAsync()).Should().NotBeNull("the fake clock never moves, so any wait would hang here");
        plc.Received.Count.Should().Be(2);
    });

    [Theory]
    [InlineData(-1, "SendInterval")]
    [InlineData(10_001, "SendInterval")]
    public void A_send_interval_out_of_range_is_refused_naming_the_option(int milliseconds, string name)
    {
        var options = new HostLinkClientOptions { SendInterval = TimeSpan.FromMilliseconds(milliseconds) };
        FluentActions.Invoking(options.Validate).Should().Throw<ArgumentOutOfRangeException>().Which.ParamName.Should().Be(name);
    }

    [Fact]
    public void A_unit_send_interval_for_a_unit_beyond_31_is_refused()
    {
        var options = new HostLinkClientOptions();
        options.UnitSendIntervals[32] = TimeSpan.FromMilliseconds(5);
        FluentActions.Invoking(options.Validate).Should().Throw<ArgumentOutOfRangeException>().WithMessage("*unit 32*");
    }
}
