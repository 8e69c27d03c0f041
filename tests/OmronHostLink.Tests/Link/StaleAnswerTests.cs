using System.Text;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Testing;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>
/// A C-mode answer carries no address, so an answer delivered out of turn (late, after the client gave up on it and
/// moved on) has the shape of a later command's. The link tells them apart by time and by what is outstanding; these
/// tests play the PLC by hand on a fake clock, so "too early" and "in time" are exact.
/// </summary>
/// <remarks>
/// The PLC's frames are golden vectors (<c>c_rd_resp_3w</c>: a 3-word RD answer, 000A FFFF 8000) or the link's own TS
/// frames echoed back, as a PLC does.
/// </remarks>
public sealed class StaleAnswerTests
{
    private static readonly LineTiming Timing = new(9600, 11);
    private static readonly TimeSpan Allowance = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(30);

    private static string RdAnswer => GoldenFrames.Frames("c_rd_resp_3w")[0];

    private static ushort[] RdWords => [0x000A, 0xFFFF, 0x8000];

    private static Task OffContext(Func<Task> test) => Task.Run(test);

    [Fact]
    public Task An_answer_complete_before_its_command_could_have_crossed_the_line_is_refused_and_the_link_fences() => OffContext(async () =>
    {
        await using var rig = Rig.Start();

        // A read whose answer goes astray: it times out, and its answer is owed.
        await rig.TimeOutAsync("D100", staysOwed: true);

        // The next read fences first; the fence's echo, in its wire time, proves the configured speed and arms the check.
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D200", 3);
        await rig.EchoFenceAsync(inWireTime: true);
        (await rig.Plc.ReadFrameAsync()).Should().StartWith("@00RD0200");

        // The late answer to D100 lands now, before D200's command could even have crossed a 9600 bps line.
        await rig.Plc.WriteAsync(RdAnswer);
        string check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS", "an answer that comes too early is put to a TS check");
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(check);

        var refused = await FluentActions.Awaiting(() => read).Should().ThrowAsync<HostLinkFrameException>();
        refused.Which.Error.Should().Be(FrameError.Stale);
        refused.Which.Message.Should().Contain("before the command and its answer could have crossed a 9600 bps line").And.Contain("late answer to an earlier command");

        // The link is out of step: the next command fences before it is sent, and since the unit's line has just
        // delivered an answer out of turn, its answer gets a TS check behind it too.
        Task<ushort[]> next = rig.Client.ReadWordsAsync("D300", 3);
        await rig.EchoFenceAsync(inWireTime: true);
        (await rig.Plc.ReadFrameAsync()).Should().StartWith("@00RD0300");
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS", "a unit whose line delivered out of turn has its answers checked for an owed answer's lifetime");
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(check);
        (await next).Should().Equal(RdWords, "an answer in its time, with the check's echo right behind it, is taken");

        // Once that lifetime has passed with nothing more out of turn, answers go unchecked again.
        rig.Time.Advance(OmronHostLink.Link.AnswerTiming.LeastOwedLifetime);
        Task<ushort[]> last = rig.Client.ReadWordsAsync("D400", 3);
        (await rig.Plc.ReadFrameAsync()).Should().StartWith("@00RD0400");
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        (await last).Should().Equal(RdWords);
        rig.Logs.WithEvent(8).Should().BeEmpty("the line runs at the configured speed");
    });

    [Fact]
    public Task An_answer_in_time_needs_no_check_when_no_answer_is_owed() => OffContext(async () =>
    {
        await using var rig = Rig.Start();
        await rig.TimeOutAsync("D100");
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D200", 3);
        await rig.EchoFenceAsync(inWireTime: true);
        string command = await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(command.Length + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);

        (await read).Should().Equal(RdWords);
        rig.Plc.Received.Should().HaveCount(3, "the timed-out command, the fence and the command: no check behind an answer in time");
    });

    [Fact]
    public Task While_a_unit_owes_an_answer_its_answers_are_checked_with_a_TS_behind_them_and_other_units_answers_are_not() => OffContext(async () =>
    {
        await using var rig = Rig.Start();

        // Unit 5's read times out: its answer may still come, and only it could pass for unit 5's answer.
        await rig.TimeOutAsync("D100", unit: 5, staysOwed: true);
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D200", 3);
        string fence = await rig.Plc.ReadFrameAsync();
        fence.Should().StartWith("@05TS", "the link fences first at the unit that failed");
        rig.Time.Advance(Timing.FrameDeadline(fence.Length, fence.Length, Allowance));
        await rig.EchoFenceAsync(inWireTime: true);
        string command = await rig.Plc.ReadFrameAsync();
        command.Should().StartWith("@00RD0200");
        rig.Time.Advance(Timing.WireTime(command.Length + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        (await read).Should().Equal(RdWords);
        rig.Plc.Received.Should().HaveCount(4, "unit 5's timed-out read, its fence, unit 0's fence and unit 0's read: no check behind unit 0's answer");

        // Unit 0's own read times out: now unit 0's next answer is checked.
        await rig.TimeOutAsync("D100", staysOwed: true);
        Task<ushort[]> checkedRead = rig.Client.ReadWordsAsync("D300", 3);
        await rig.EchoFenceAsync(inWireTime: true);
        command = await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(command.Length + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        string check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS", "a late answer to unit 0's timed-out read could pass for this one's: a TS behind it shows whether another frame follows");
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(check);
        (await checkedRead).Should().Equal(RdWords);
    });

    [Fact]
    public Task A_line_faster_than_configured_is_named_once_and_its_answers_are_taken() => OffContext(async () =>
    {
        await using var rig = Rig.Start();
        await rig.TimeOutAsync("D100");

        // The fence comes back at once: faster than 9600 bps allows. Nothing fails; one warning names the setting.
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D200", 3);
        await rig.EchoFenceAsync(inWireTime: false);
        await rig.Plc.ReadFrameAsync();
        await rig.Plc.WriteAsync(RdAnswer);
        (await read).Should().Equal(RdWords);

        await rig.TimeOutAsync("D100");
        Task<ushort[]> again = rig.Client.ReadWordsAsync("D200", 3);
        await rig.EchoFenceAsync(inWireTime: false);
        await rig.Plc.ReadFrameAsync();
        await rig.Plc.WriteAsync(RdAnswer);
        (await again).Should().Equal(RdWords);

        LogEntry warning = rig.Logs.WithEvent(8).Should().ContainSingle("the line is named once").Subject;
        warning.Level.Should().Be(LogLevel.Warning);
        warning.Message.Should().Contain("Serial:BaudRate").And.Contain("9600 bps");
    });

    [Fact]
    public Task An_early_answer_on_a_line_that_proves_faster_than_configured_stands() => OffContext(async () =>
    {
        await using var rig = Rig.Start();
        await rig.TimeOutAsync("D100", staysOwed: true);
        Task<ushort[]> first = rig.Client.ReadWordsAsync("D200", 3);
        await rig.EchoFenceAsync(inWireTime: true);
        await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        string inTime = await rig.Plc.ReadFrameAsync();
        inTime.Should().StartWith("@00TS", "an answer is owed: the answer gets a check behind it");
        rig.Time.Advance(Timing.WireTime(2 * inTime.Length));
        await rig.Plc.WriteAsync(inTime);
        await first;

        // Armed; now an answer comes at once, and so does the check behind it: the line is faster than configured.
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D300", 3);
        await rig.Plc.ReadFrameAsync();
        await rig.Plc.WriteAsync(RdAnswer);
        string check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS");
        await rig.Plc.WriteAsync(check);

        (await read).Should().Equal(RdWords, "the check came back next and as fast: the answer was this command's");
        rig.Logs.WithEvent(8).Should().ContainSingle();
    });

    [Fact]
    public Task An_early_answer_of_a_unit_that_owes_nothing_stands_without_a_check() => OffContext(async () =>
    {
        await using var rig = Rig.Start();

        // Unit 5 owes an answer and the fence arms the checks; unit 0 owes nothing, so it has no late answer to give.
        await rig.TimeOutAsync("D100", unit: 5, staysOwed: true);
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D200", 3);
        string fence = await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(2 * fence.Length));
        await rig.Plc.WriteAsync(fence);
        (await rig.Plc.ReadFrameAsync()).Should().StartWith("@00RD0200");
        await rig.Plc.WriteAsync(RdAnswer);

        (await read).Should().Equal(RdWords, "an early answer is stale only where a late one is due");
        rig.Plc.Received.Should().HaveCount(3, "unit 5's read, its fence and unit 0's read: no check");
    });

    [Fact]
    public Task A_frame_that_arrives_while_nothing_is_outstanding_makes_the_next_command_fence_first() => OffContext(async () =>
    {
        await using var rig = Rig.Start();
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D100", 3);
        await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        await read;

        // An answer nobody asked for: the line is out of step.
        await rig.Plc.WriteAsync(RdAnswer);
        SpinWait.SpinUntil(() => rig.Client.Connection.Held > 0, Limit).Should().BeTrue();

        Task<ushort[]> next = rig.Client.ReadWordsAsync("D200", 3);
        (await rig.Plc.ReadFrameAsync()).Should().StartWith("@00TS", "the stray frame is discarded and the link fences before the command");
        rig.Plc.Received.Should().HaveCount(2);
        await rig.EchoFenceAsync(inWireTime: true, alreadyRead: rig.Plc.Received.Last());
        string command = await rig.Plc.ReadFrameAsync();
        command.Should().StartWith("@00RD0200");
        rig.Time.Advance(Timing.WireTime(command.Length + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        string check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS", "the stray frame shows the unit's line delivers out of turn: the answer gets a check behind it");
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(check);
        (await next).Should().Equal(RdWords);
    });

    [Fact]
    public Task With_VerifyAnswers_each_answer_is_taken_only_when_the_check_behind_it_comes_back_next() => OffContext(async () =>
    {
        await using var rig = Rig.Start(o => o.VerifyAnswers = true);
        Task<ushort[]> read = rig.Client.ReadWordsAsync("D100", 3);
        await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        string check = await rig.Plc.ReadFrameAsync();
        check.Should().StartWith("@00TS");
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(check);
        (await read).Should().Equal(RdWords);

        // An answer in time, but another frame comes between it and the check's echo: the line delivers out of turn.
        Task<ushort[]> second = rig.Client.ReadWordsAsync("D200", 3);
        await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(17 + RdAnswer.Length));
        await rig.Plc.WriteAsync(RdAnswer);
        check = await rig.Plc.ReadFrameAsync();
        rig.Time.Advance(Timing.WireTime(2 * check.Length));
        await rig.Plc.WriteAsync(RdAnswer + check);
        var refused = await FluentActions.Awaiting(() => second).Should().ThrowAsync<HostLinkFrameException>();
        refused.Which.Error.Should().Be(FrameError.Stale);
        refused.Which.Message.Should().Contain("between the answer to RD from unit 00 and the TS check");
    });

    [Fact]
    public async Task With_VerifyAnswers_a_check_follows_C_mode_answers_and_not_FINS_answers()
    {
        var simulator = new VirtualPlc();
        simulator.WriteWords(PlcArea.Dm, 100, [0x1234]);
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = simulator.RunAsync(plcEnd, stop.Token);
        await using (var client = HostLinkClient.ForStream(host, new HostLinkClientOptions { VerifyAnswers = true, TurnaroundAllowance = TimeSpan.FromSeconds(5) }))
        {
            var sent = new System.Collections.Concurrent.ConcurrentQueue<string>();
            client.Connection.FrameObserver = (outgoing, bytes) =>
            {
                if (outgoing)
                {
                    sent.Enqueue(Encoding.ASCII.GetString(bytes.Span));
                }
            };

            (await client.ReadWordsAsync("D100", 1)).Should().Equal((ushort)0x1234);
            (await client.Unit(0, HostLinkCommandSet.Fins).ReadWordsAsync("D100", 1)).Should().Equal((ushort)0x1234);
            (await client.TestAsync("HELLO")).Should().BePositive();

            sent.Select(f => f.Substring(3, 2)).Should().Equal(["RD", "TS", "FA", "TS"], "RD is checked; FINS carries its service ID and TS its own text");
        }

        stop.Cancel();
        await session;
    }

    /// <summary>A client on a fake clock with the PLC's end of an in-memory line played by the test.</summary>
    private sealed class Rig : IAsyncDisposable
    {
        private Rig(HostLinkClient client, ManualPlc plc, FakeTimeProvider time, CapturingLoggerProvider logs, ILoggerFactory factory)
        {
            Client = client;
            Plc = plc;
            Time = time;
            Logs = logs;
            Factory = factory;
        }

        public HostLinkClient Client { get; }

        public ManualPlc Plc { get; }

        public FakeTimeProvider Time { get; }

        public CapturingLoggerProvider Logs { get; }

        private ILoggerFactory Factory { get; }

        public static Rig Start(Action<HostLinkClientOptions>? configure = null)
        {
            var time = new FakeTimeProvider();
            var logs = new CapturingLoggerProvider();
            ILoggerFactory factory = LoggerFactory.Create(b => b.SetMinimumLevel(LogLevel.Debug).AddProvider(logs));
            (Stream host, Stream plc) = InMemoryLink.CreatePair();
            var options = new HostLinkClientOptions
            {
                LineTiming = Timing,
                TurnaroundAllowance = Allowance,
                ReadRetries = 0,
                TimeProvider = time,
                LoggerFactory = factory,
            };
            configure?.Invoke(options);
            return new Rig(HostLinkClient.ForStream(host, options), new ManualPlc(plc), time, logs, factory);
        }

        /// <summary>
        /// A read of 3 words at <paramref name="address"/> of <paramref name="unit"/> that nobody answers, run to its
        /// timeout. Unless <paramref name="staysOwed"/>, its answer is then waited for past its lifetime as an owed answer
        /// (<see cref="OmronHostLink.Link.AnswerTiming.LeastOwedLifetime"/>), so later answers get no TS check for it.
        /// </summary>
        public async Task TimeOutAsync(string address, int unit = 0, bool staysOwed = false)
        {
            Task<ushort[]> read = Client.Unit(unit).ReadWordsAsync(address, 3);
            (await Plc.ReadFrameAsync()).Should().StartWith($"@{unit:D2}RD", "the link is in step: the command goes out at once");
            Time.Advance(TimeSpan.FromSeconds(1));
            await FluentActions.Awaiting(() => read).Should().ThrowAsync<HostLinkTimeoutException>();
            if (!staysOwed)
            {
                Time.Advance(OmronHostLink.Link.AnswerTiming.LeastOwedLifetime);
            }
        }

        /// <summary>Reads the fence the link sends (unless already read) and echoes it, after its wire time both ways or at once.</summary>
        public async Task EchoFenceAsync(bool inWireTime, string? alreadyRead = null)
        {
            string fence = alreadyRead ?? await Plc.ReadFrameAsync();
            fence.Should().StartWith("@00TS");
            if (inWireTime)
            {
                Time.Advance(Timing.WireTime(2 * fence.Length));
            }

            await Plc.WriteAsync(fence);
        }

        public async ValueTask DisposeAsync()
        {
            await Client.DisposeAsync();
            await Plc.DisposeAsync();
            Factory.Dispose();
        }
    }

    /// <summary>The PLC's end of the line, read frame by frame and written by the test.</summary>
    private sealed class ManualPlc(Stream stream) : IAsyncDisposable
    {
        public List<string> Received { get; } = new();

        public async Task<string> ReadFrameAsync()
        {
            using var timeout = new CancellationTokenSource(Limit);
            var frame = new StringBuilder();
            var one = new byte[1];
            while (true)
            {
                int n = await stream.ReadAsync(one, timeout.Token);
                if (n == 0)
                {
                    throw new EndOfStreamException("The client closed the line.");
                }

                frame.Append((char)one[0]);
                if (one[0] == (byte)'\r')
                {
                    Received.Add(frame.ToString());
                    return frame.ToString();
                }
            }
        }

        public async Task WriteAsync(string text)
        {
            await stream.WriteAsync(Encoding.ASCII.GetBytes(text));
            await stream.FlushAsync();
        }

        public ValueTask DisposeAsync() => stream.DisposeAsync();
    }
}
