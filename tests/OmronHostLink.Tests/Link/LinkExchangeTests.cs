using OmronHostLink.Transports;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Link;

/// <summary>The link against a scripted PLC: framing, validation, handshakes, deadlines and resynchronisation.</summary>
public sealed class LinkExchangeTests
{
    // Frames below come from ../shared/hostlink/vectors.json (named), or are built with the test's own FCS.
    private const string RdD100x3 = "@00RD0100000354*\r"; // roof_rd_d100_3
    private const string Rd3WordsResponse = "@00RD00000AFFFF80002F*\r"; // c_rd_resp_3w

    // The allowance of the tests whose PLC stays silent or answers late: the deadline is what they check.
    private static readonly TimeSpan DeadlineAllowance = TimeSpan.FromMilliseconds(150);

    private static HostLinkClientOptions FastOptions(int retries = 0, TimeSpan? allowance = null) => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = allowance ?? Allowances.LosslessLine,
        ReadRetries = retries,
    };

    private static (HostLinkClient Client, ScriptedPlc Plc) Connect(Func<string, Reply?> handler, HostLinkClientOptions? options = null)
    {
        (Stream host, Stream plc) = InMemoryLink.CreatePair();
        return (HostLinkClient.ForStream(host, options ?? FastOptions()), new ScriptedPlc(plc, handler));
    }

    [Theory]
    [InlineData(0)] // whole
    [InlineData(1)] // one byte at a time
    [InlineData(-1)] // random chunks
    public async Task Reads_words_from_an_answer_in_any_fragmentation(int chunk)
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply(Rd3WordsResponse, ChunkSize: chunk) : null);
        await using var _ = plc;
        await using var __ = client;

        ushort[] words = await client.ReadWordsAsync("D100", 3);

        words.Should().Equal(0x000A, 0xFFFF, 0x8000);
        plc.Received.Should().ContainSingle().Which.Should().Be(RdD100x3);
    }

    [Fact]
    public async Task Noise_before_the_answer_is_skipped()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply("\x00\x7F#\r~~" + Rd3WordsResponse) : null);
        await using var _ = plc;
        await using var __ = client;

        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);
    }

    [Fact]
    public async Task An_answer_with_a_bad_FCS_is_an_error_never_a_value()
    {
        // fieldlink_rd_cmd / fieldlink_rd_resp_fake (placeholder FCS 00)
        var (client, plc) = Connect(f => f == "@00RD0100000255*\r" ? new Reply("@00RD001234ABCD00*\r") : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 2)).Should().ThrowAsync<HostLinkFrameException>();
        e.Which.Error.Should().Be(FrameError.BadFcs);
    }

    [Fact]
    public async Task An_answer_from_another_unit_is_refused()
    {
        // py_wr_resp_unit1: "@01WR0044*\r" answers a WR to unit 00 (cs_wr_cio0_000C)
        var (client, plc) = Connect(f => f.StartsWith("@00WR", StringComparison.Ordinal) ? new Reply("@01WR0044*\r") : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.WriteWordAsync("CIO0", 0x000C)).Should().ThrowAsync<HostLinkFrameException>();
        e.Which.Error.Should().Be(FrameError.WrongUnit);
        plc.Received.Should().Contain("@00WR0000000C36*\r");
    }

    [Fact]
    public async Task An_answer_with_another_header_is_refused()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply("@00WD0053*\r") : null); // roof_wd_resp_ok
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkFrameException>();
        e.Which.Error.Should().Be(FrameError.WrongHeader);
    }

    [Fact]
    public async Task A_truncated_answer_is_refused()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply(TestFrames.Final("@00RD00000AFFFF")) : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkFrameException>();
        e.Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public async Task A_frame_cut_before_its_CR_times_out()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply(Rd3WordsResponse.TrimEnd('\r')) : null, FastOptions(allowance: DeadlineAllowance));
        await using var _ = plc;
        await using var __ = client;

        await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkTimeoutException>();
    }

    [Fact]
    public async Task End_codes_raise_the_end_code_exception_with_code_header_and_unit()
    {
        // wdpy_wd_d9 answered by c_wd_resp_01 (not executable in RUN mode)
        var (client, plc) = Connect(f => f == "@00WD000900015B*\r" ? new Reply("@00WD0152*\r") : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.WriteWordAsync("D9", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
        e.Which.EndCode.Should().Be(EndCode.NotExecutableInRunMode);
        e.Which.Header.Should().Be("WD");
        e.Which.Unit.Should().Be(0);
        e.Which.Category.Should().Be(EndCodeCategory.ModeNotAllowed);
        e.Which.Message.Should().Contain("01").And.Contain("RUN");
    }

    [Fact]
    public async Task IC_means_the_header_is_not_supported()
    {
        var (client, plc) = Connect(f => f.StartsWith("@00MM", StringComparison.Ordinal) ? new Reply("@00IC4A*\r") : null); // c_ic_resp
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadModelAsync()).Should().ThrowAsync<HostLinkEndCodeException>();
        e.Which.EndCode.Should().Be(EndCode.UndefinedHeader);
        e.Which.Category.Should().Be(EndCodeCategory.NotSupported);
    }

    [Fact]
    public async Task A_late_answer_to_a_timed_out_request_is_never_returned_for_the_next_one()
    {
        int calls = 0;
        string fresh = TestFrames.Final("@00RD00" + TestFrames.Words(new ushort[] { 1, 2, 3 }));
        var (client, plc) = Connect(f =>
        {
            if (f != RdD100x3)
            {
                return null;
            }

            // The first answer comes long after the client's deadline; the second is the fresh one.
            return Interlocked.Increment(ref calls) == 1 ? new Reply(Rd3WordsResponse, TimeSpan.FromMilliseconds(400)) : new Reply(fresh);
        }, FastOptions(retries: 2, allowance: DeadlineAllowance));
        await using var _ = plc;
        await using var __ = client;

        using (var once = new CancellationTokenSource(TimeSpan.FromMilliseconds(250)))
        {
            // Cut the first call at its deadline-ish point so that it cannot retry into the late answer.
            await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3, once.Token)).Should().ThrowAsync<Exception>();
        }

        ushort[] next = await client.ReadWordsAsync("D100", 3);

        next.Should().Equal(1, 2, 3);
        plc.Received.Should().Contain(f => f.StartsWith("@00TS", StringComparison.Ordinal), "the link fences with TS after a failure");
    }

    [Fact]
    public async Task Reads_are_retried_after_damage_and_writes_are_not()
    {
        int reads = 0;
        int writes = 0;
        var (client, plc) = Connect(
            f =>
            {
                if (f == RdD100x3)
                {
                    return Interlocked.Increment(ref reads) == 1 ? new Reply("@00RD1354*\r") : new Reply(Rd3WordsResponse); // c_rd_err_13 first
                }

                if (f.StartsWith("@00WD", StringComparison.Ordinal))
                {
                    Interlocked.Increment(ref writes);
                    return new Reply("@00WDA321*\r"); // c_wd_err_A3
                }

                return null;
            },
            FastOptions(retries: 2));
        await using var _ = plc;
        await using var __ = client;

        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);
        reads.Should().Be(2);

        var e = await FluentActions.Awaiting(() => client.WriteWordAsync("D9", 1)).Should().ThrowAsync<HostLinkEndCodeException>();
        e.Which.EndCode.Should().Be(EndCode.AbortedFcsError);
        writes.Should().Be(1);
    }

    [Fact]
    public async Task A_multi_frame_answer_is_asked_for_frame_by_frame_with_a_bare_CR()
    {
        // c_rd_multi_response_40w, answered to its command from the vector notes.
        string[] frames = GoldenFrames.Rd40Frames;
        int next = 0;
        var (client, plc) = Connect(f =>
        {
            if (f == "@00RD0000004052*\r" || f == "\r")
            {
                return new Reply(frames[next++]);
            }

            return null;
        });
        await using var _ = plc;
        await using var __ = client;

        ushort[] words = await client.ReadWordsAsync("D0", 40);

        words.Should().Equal(Enumerable.Range(0, 40).Select(i => (ushort)(0x1000 + i)));
        plc.Received.Should().Equal("@00RD0000004052*\r", "\r");
    }

    [Fact]
    public async Task A_multi_frame_write_waits_for_the_PLC_CR_between_frames()
    {
        string[] frames = GoldenFrames.Wd50Frames;
        var (client, plc) = Connect(f =>
        {
            if (f == frames[0])
            {
                return new Reply("\r");
            }

            return f == frames[1] ? new Reply("@00WD0053*\r") : null;
        });
        await using var _ = plc;
        await using var __ = client;

        await client.WriteWordsAsync("D1000", GoldenFrames.Wd50Words);

        plc.Received.Should().Equal(frames);
    }

    [Fact]
    public async Task Cancelling_in_the_middle_of_a_multi_frame_answer_resets_the_line_before_the_next_exchange()
    {
        string[] frames = GoldenFrames.Rd40Frames;
        var (client, plc) = Connect(f => f == "@00RD0000004052*\r" ? new Reply(frames[0]) : f == RdD100x3 ? new Reply(Rd3WordsResponse) : null);
        await using var _ = plc;
        await using var __ = client;
        using var cts = new CancellationTokenSource();
        client.FrameObserver = (sent, frame) =>
        {
            if (sent && frame.Length == 1)
            {
                cts.Cancel(); // cancel as the link asks for frame 2
            }
        };

        await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 40, cts.Token)).Should().ThrowAsync<OperationCanceledException>();
        client.FrameObserver = null;
        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);

        plc.Received.Should().Contain("@**\r");
    }

    [Fact]
    public async Task Concurrent_callers_never_interleave_on_the_wire()
    {
        var (client, plc) = Connect(f =>
        {
            // RD dddd 0001 → answer the word number itself, so every caller can check it got its own answer.
            if (f.Length == 17 && f.StartsWith("@00RD", StringComparison.Ordinal))
            {
                ushort word = ushort.Parse(f.Substring(5, 4), System.Globalization.CultureInfo.InvariantCulture);
                return new Reply(TestFrames.Final("@00RD00" + TestFrames.Words(new[] { word })), ChunkSize: -1);
            }

            return null;
        });
        await using var _ = plc;
        await using var __ = client;

        ushort[][] results = await Task.WhenAll(Enumerable.Range(0, 50).Select(i => client.ReadWordsAsync($"D{i}", 1)));

        results.Select(r => r[0]).Should().Equal(Enumerable.Range(0, 50).Select(i => (ushort)i));
    }

    [Fact]
    public async Task Unit_views_share_the_link_and_address_their_own_unit()
    {
        var (client, plc) = Connect(f =>
        {
            if (f.Length > 5 && f.Substring(3, 2) == "MM")
            {
                string unit = f.Substring(1, 2);
                return new Reply(TestFrames.Final($"@{unit}MM00" + (unit == "05" ? "30" : "12")));
            }

            return null;
        });
        await using var _ = plc;
        await using var __ = client;

        PlcModel[] models = await Task.WhenAll(client.Unit(5).ReadModelAsync(), client.Unit(7).ReadModelAsync());

        models[0].Code.Should().Be(0x30);
        models[1].Code.Should().Be(0x12);
        plc.Received.Should().Contain("@05MM5B*\r".Replace("5B", TestFrames.Fcs("@05MM"), StringComparison.Ordinal));
    }

    [Fact]
    public async Task A_silent_unit_times_out_within_its_deadline()
    {
        var (client, plc) = Connect(_ => Reply.None, FastOptions(allowance: DeadlineAllowance));
        await using var _ = plc;
        await using var __ = client;
        var clock = System.Diagnostics.Stopwatch.StartNew();

        await FluentActions.Awaiting(() => client.ReadStatusAsync()).Should().ThrowAsync<HostLinkTimeoutException>();

        clock.Elapsed.Should().BeLessThan(TimeSpan.FromSeconds(1));
    }

    [Fact]
    public async Task A_closed_stream_is_a_connection_error()
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        await using var client = HostLinkClient.ForStream(host, FastOptions());
        await plcEnd.DisposeAsync();

        await FluentActions.Awaiting(() => client.ReadStatusAsync()).Should().ThrowAsync<HostLinkConnectionException>();
    }

    [Fact]
    public async Task A_line_that_echoes_our_frame_does_not_make_the_echo_the_answer()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply(RdD100x3 + Rd3WordsResponse) : null);
        await using var _ = plc;
        await using var __ = client;

        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);
    }

    [Fact]
    public async Task A_damaged_fence_answer_is_followed_by_a_second_fence()
    {
        int reads = 0;
        int fences = 0;
        var (client, plc) = Connect(f =>
        {
            if (f == RdD100x3)
            {
                return Interlocked.Increment(ref reads) == 1 ? Reply.None : new Reply(Rd3WordsResponse);
            }

            if (f.StartsWith("@00TS", StringComparison.Ordinal))
            {
                // The first fence's echo arrives damaged (one character changed), the second intact.
                return Interlocked.Increment(ref fences) == 1 ? new Reply(f.Substring(0, 6) + (f[6] == '0' ? '1' : '0') + f.Substring(7)) : new Reply(f);
            }

            return null;
        }, FastOptions(allowance: DeadlineAllowance));
        await using var _ = plc;
        await using var __ = client;

        await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkTimeoutException>();
        (await client.ReadWordsAsync("D100", 3)).Should().Equal(0x000A, 0xFFFF, 0x8000);

        fences.Should().Be(2);
    }
}
