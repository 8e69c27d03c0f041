using System.Collections.Concurrent;
using System.Diagnostics;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>The <c>OmronHostLink</c> activity source: one client span per command, seen through an <see cref="ActivityListener"/>.</summary>
public sealed class ActivityTests : IDisposable
{
    private readonly ConcurrentQueue<Activity> _stopped = new();
    private readonly ActivityListener _listener;

    public ActivityTests()
    {
        _listener = new ActivityListener
        {
            ShouldListenTo = source => source.Name == HostLinkTelemetry.ActivitySourceName,
            Sample = (ref ActivityCreationOptions<ActivityContext> _) => ActivitySamplingResult.AllDataAndRecorded,
            ActivityStopped = _stopped.Enqueue,
        };
        ActivitySource.AddActivityListener(_listener);
    }

    [Fact]
    public async Task Each_command_is_one_client_span_with_the_command_unit_link_frames_and_end_code()
    {
        await using var line = TelemetryLine.Start(TelemetryLine.Options("span-press"));

        await line.Client.ReadWordsAsync("D0", 2);
        await line.Client.ReadWordsAsync("D0", 100); // 100 words come back in four frames (30 + 31 + 31 + 8)
        await line.Client.ReadStatusAsync();

        Activity[] spans = Spans("span-press");
        spans.Select(s => s.DisplayName).Should().Equal("HostLink RD", "HostLink RD", "HostLink MS");
        spans.Should().OnlyContain(s => s.Kind == ActivityKind.Client && s.Status == ActivityStatusCode.Unset && s.Source.Name == "OmronHostLink");
        Activity first = spans[0];
        first.GetTagItem("hostlink.command").Should().Be("RD");
        first.GetTagItem("hostlink.unit").Should().Be(0);
        first.GetTagItem("hostlink.link.name").Should().Be("span-press");
        first.GetTagItem("hostlink.transport").Should().Be("stream");
        first.GetTagItem("hostlink.frames.sent").Should().Be(1);
        first.GetTagItem("hostlink.frames.received").Should().Be(1);
        first.GetTagItem("hostlink.retry_count").Should().Be(0);
        first.GetTagItem("hostlink.end_code").Should().Be("00");
        first.GetTagItem("error.type").Should().BeNull();
        spans[1].GetTagItem("hostlink.frames.received").Should().Be(4);
    }

    [Fact]
    public async Task A_retried_command_is_still_one_span_counting_both_attempts()
    {
        HostLinkClientOptions options = TelemetryLine.Options("span-retry");
        options.ReadRetries = 2;
        await using var line = TelemetryLine.Start(options);

        line.CorruptNextAnswer();
        await line.Client.ReadWordsAsync("D0", 1);

        Activity span = Spans("span-retry").Should().ContainSingle().Subject;
        span.Status.Should().Be(ActivityStatusCode.Unset);
        span.GetTagItem("hostlink.retry_count").Should().Be(1);
        span.GetTagItem("hostlink.frames.sent").Should().Be(2, "the command went out twice (the resynchronisation's fence is not the command's)");
        span.GetTagItem("hostlink.frames.received").Should().Be(2, "the damaged answer and the good one");
    }

    [Fact]
    public async Task A_failed_command_is_an_error_span_with_its_error_type_and_end_code()
    {
        // The refusal on a line with the in-process allowance (a busy machine must not turn it into a timeout); the
        // silent unit on a line of the same name with a short one.
        HostLinkClientOptions options = TelemetryLine.Options("span-fail");
        await using var line = TelemetryLine.Start(options, new VirtualPlcOptions { InitialMode = PlcMode.Run });
        HostLinkClientOptions silentOptions = TelemetryLine.Options("span-fail");
        silentOptions.TurnaroundAllowance = TimeSpan.FromMilliseconds(100);
        silentOptions.ReadRetries = 1;
        await using var silentLine = TelemetryLine.Start(silentOptions);

        await FluentActions.Awaiting(() => line.Client.WriteWordAsync("D0", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
        await FluentActions.Awaiting(() => silentLine.Client.Unit(9).ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();

        Activity[] spans = Spans("span-fail");
        spans.Should().HaveCount(2);
        Activity refused = spans[0];
        refused.Status.Should().Be(ActivityStatusCode.Error);
        refused.StatusDescription.Should().Contain("RUN");
        refused.GetTagItem("error.type").Should().Be("NotExecutableInRunMode");
        refused.GetTagItem("hostlink.end_code").Should().Be("01");
        refused.GetTagItem("hostlink.command").Should().Be("WD");
        refused.Events.Should().ContainSingle(e => e.Name == "exception");

        Activity unanswered = spans[1];
        unanswered.Status.Should().Be(ActivityStatusCode.Error);
        unanswered.GetTagItem("error.type").Should().Be("timeout");
        unanswered.GetTagItem("hostlink.unit").Should().Be(9);
        unanswered.GetTagItem("hostlink.retry_count").Should().Be(1);
        unanswered.GetTagItem("hostlink.end_code").Should().BeNull("no answer, no end code");
    }

    [Fact]
    public async Task The_span_is_a_child_of_the_callers_activity_and_leaves_it_current()
    {
        await using var line = TelemetryLine.Start(TelemetryLine.Options("span-parent"));
        using var caller = new Activity("poll").Start();

        await line.Client.ReadWordsAsync("D0", 1);

        Activity.Current.Should().BeSameAs(caller);
        Activity span = Spans("span-parent").Should().ContainSingle().Subject;
        span.ParentSpanId.Should().Be(caller.SpanId);
        span.TraceId.Should().Be(caller.TraceId);
    }

    public void Dispose() => _listener.Dispose();

    private Activity[] Spans(string link)
        => _stopped.Where(a => (string?)a.GetTagItem("hostlink.link.name") == link).ToArray();
}
