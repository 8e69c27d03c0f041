using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>
/// Deadlines, retries and resynchronisation on a fake clock: the link arms each frame's deadline on its
/// <see cref="TimeProvider"/>, so these tests move time by hand and see each step happen exactly when it is due.
/// </summary>
/// <remarks>
/// Each test runs off the test runner's synchronization context (<see cref="OffContext"/>): there, what a deadline
/// sets off runs to its end inside <see cref="FakeTimeProvider.Advance"/>, so "not yet" and "now" are exact.
/// </remarks>
public sealed class LinkDeadlineTests
{
    private static readonly LineTiming Timing = new(115200, 11);
    private static readonly TimeSpan Allowance = TimeSpan.FromMilliseconds(150);

    /// <summary>MS: 9 characters sent, the longest first answer frame 31 (end code, status word, 16-character message).</summary>
    private static readonly TimeSpan StatusDeadline = Timing.WireTime(9 + 31) + Allowance;

    /// <summary>A TS fence: 17 characters sent and the same 17 echoed.</summary>
    private static readonly TimeSpan FenceDeadline = Timing.WireTime(17 + 17) + Allowance;

    private static Task OffContext(Func<Task> test) => Task.Run(test);

    private static (HostLinkClient Client, ScriptedPlc Plc, FakeTimeProvider Time) SilentUnit(int retries)
    {
        var time = new FakeTimeProvider();
        (Stream host, Stream plc) = InMemoryLink.CreatePair();
        var client = HostLinkClient.ForStream(host, new HostLinkClientOptions
        {
            LineTiming = Timing,
            TurnaroundAllowance = Allowance,
            ReadRetries = retries,
            TimeProvider = time,
        });

        // Nothing is ever answered, TS fences included.
        return (client, new ScriptedPlc(plc, _ => Reply.None), time);
    }

    [Fact]
    public Task A_silent_unit_fails_exactly_at_its_frame_deadline() => OffContext(async () =>
    {
        var (client, plc, time) = SilentUnit(retries: 0);
        await using var _ = plc;
        await using var __ = client;

        Task<PlcStatus> call = client.ReadStatusAsync();
        time.Advance(StatusDeadline - TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeFalse("the deadline is the wire time of the command and the longest answer plus the allowance");

        time.Advance(TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeTrue();
        var e = await FluentActions.Awaiting(() => call).Should().ThrowAsync<HostLinkTimeoutException>();
        e.Which.Timeout.Should().Be(StatusDeadline);
    });

    [Fact]
    public Task A_retry_first_fences_twice_each_fence_on_its_own_deadline() => OffContext(async () =>
    {
        var (client, plc, time) = SilentUnit(retries: 1);
        await using var _ = plc;
        await using var __ = client;

        Task<PlcStatus> call = client.ReadStatusAsync();
        time.Advance(StatusDeadline);
        call.IsCompleted.Should().BeFalse("the first attempt timed out; the retry resynchronises first");

        time.Advance(FenceDeadline - TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeFalse("the first fence is still within its deadline");
        time.Advance(TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeFalse("an unanswered fence is followed by a second one");

        time.Advance(FenceDeadline - TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeFalse();
        time.Advance(TimeSpan.FromMilliseconds(1));
        call.IsCompleted.Should().BeTrue();
        var e = await FluentActions.Awaiting(() => call).Should().ThrowAsync<HostLinkTimeoutException>();
        e.Which.Message.Should().Contain("to MS").And.Contain("2 attempts");
        e.Which.InnerException!.Message.Should().Contain("TS check");
        plc.ReceivedCount(f => f.StartsWith("@00TS", StringComparison.Ordinal)).Should().BeLessThanOrEqualTo(2);
    });

    [Fact]
    public Task Cancelling_a_waiting_call_ends_it_at_once_and_the_next_call_resynchronises() => OffContext(async () =>
    {
        var (client, plc, time) = SilentUnit(retries: 0);
        await using var _ = plc;
        await using var __ = client;
        using var cts = new CancellationTokenSource();

        Task<PlcStatus> call = client.ReadStatusAsync(cts.Token);
        time.Advance(TimeSpan.FromMilliseconds(10));
        await cts.CancelAsync();

        call.IsCompleted.Should().BeTrue("cancellation does not wait for the deadline");
        await FluentActions.Awaiting(() => call).Should().ThrowAsync<OperationCanceledException>();

        Task<PlcStatus> next = client.ReadStatusAsync();
        time.Advance(FenceDeadline);
        time.Advance(FenceDeadline);
        var e = await FluentActions.Awaiting(() => next).Should().ThrowAsync<HostLinkTimeoutException>();
        e.Which.InnerException!.Message.Should().Contain("TS check", "the link fences after a cancelled exchange");
    });

    [Fact]
    public Task An_answer_that_came_after_its_deadline_is_a_timeout_even_before_the_deadline_timer_has_run() => OffContext(async () =>
    {
        const string Ms = "@00MS5E*\r";
        byte[] answer = System.Text.Encoding.ASCII.GetBytes(TestFrames.Final("@00MS00" + "0000"));
        var time = new TimerRecordingTimeProvider();
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        await using var plc = new ScriptedPlc(plcEnd, f => f == Ms ? Reply.None : null); // MS answered below; TS echoed
        await using var client = HostLinkClient.ForStream(host, new HostLinkClientOptions
        {
            LineTiming = Timing,
            TurnaroundAllowance = Allowance,
            ReadRetries = 0,
            TimeProvider = time,
        });

        // The link's clock runs on while its timers wait (a busy host): only when the answer came decides.
        Task<PlcStatus> onTime = client.ReadStatusAsync();
        await Eventually.UntilAsync(() => plc.ReceivedCount(f => f == Ms) == 1, "the PLC received the first MS");
        time.AdvanceWithoutTimers(StatusDeadline - TimeSpan.FromMilliseconds(1));
        await plcEnd.WriteAsync(answer);
        (await onTime).Mode.Should().Be(PlcMode.Program, "the answer came 1 ms before its deadline");

        Task<PlcStatus> late = client.ReadStatusAsync();
        await Eventually.UntilAsync(() => plc.ReceivedCount(f => f == Ms) == 2, "the PLC received the second MS");
        time.AdvanceWithoutTimers(StatusDeadline + TimeSpan.FromMilliseconds(1));
        await plcEnd.WriteAsync(answer);
        var e = await FluentActions.Awaiting(() => late).Should().ThrowAsync<HostLinkTimeoutException>("the answer came 1 ms after its deadline");
        e.Which.Message.Should().Contain("No answer");

        // The late answer was left for the fence before the next command to discard: it is not taken for that command's.
        Task<PlcStatus> next = client.ReadStatusAsync();
        await Eventually.UntilAsync(() => plc.ReceivedCount(f => f == Ms) == 3, "the PLC received the third MS");
        plc.Received.Should().Contain(f => f.StartsWith("@00TS", StringComparison.Ordinal), "the link fenced after the timeout");
        next.IsCompleted.Should().BeFalse("the late answer was discarded by the fence");
        await plcEnd.WriteAsync(answer);
        (await next).Mode.Should().Be(PlcMode.Program);
    });
}
