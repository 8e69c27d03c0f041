using OmronHostLink.Link;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Protocol;

/// <summary>
/// <see cref="HostLinkException.IsTransient"/>: what may succeed when tried again (timeouts, damaged frames, a lost
/// link, line-damage end codes, a busy network) and what fails the same way every time.
/// </summary>
public sealed class IsTransientTests
{
    private const string RdD100x3 = "@00RD0100000354*\r"; // roof_rd_d100_3

    // W342 end codes: 13 and A3 report a frame the PLC received damaged (10-12 and A0-A2 on CV-series).
    [Theory]
    [InlineData(0x13, true)]
    [InlineData(0xA3, true)]
    [InlineData(0x10, true)]
    [InlineData(0x11, true)]
    [InlineData(0x12, true)]
    [InlineData(0xA0, true)]
    [InlineData(0xA1, true)]
    [InlineData(0xA2, true)]
    [InlineData(0x01, false)]
    [InlineData(0x02, false)]
    [InlineData(0x0B, false)]
    [InlineData(0x14, false)]
    [InlineData(0x15, false)]
    [InlineData(0x16, false)]
    [InlineData(0x18, false)]
    [InlineData(0x21, false)]
    [InlineData(0x23, false)]
    [InlineData(0xA4, false)]
    [InlineData(0xA5, false)]
    [InlineData(0x1C0, false)] // IC
    public void C_mode_end_codes_are_transient_only_for_line_damage(int code, bool transient)
    {
        var e = new HostLinkEndCodeException((EndCode)code, "RD", 0);

        e.IsTransient.Should().Be(transient);
        ((EndCode)code).IsTransient().Should().Be(transient);
    }

    // W342 section 5-1-3: 0102 token timeout, 0103 retries failed, 0104 too many send frames, 0204 destination busy,
    // 0205 response timeout; the relay and CPU error flags do not change the answer.
    [Theory]
    [InlineData(0x0102, true)]
    [InlineData(0x0103, true)]
    [InlineData(0x0104, true)]
    [InlineData(0x0204, true)]
    [InlineData(0x0205, true)]
    [InlineData(0x8204, true)]
    [InlineData(0x02C4, true)]
    [InlineData(0x0401, false)]
    [InlineData(0x1001, false)]
    [InlineData(0x1103, false)]
    [InlineData(0x2101, false)]
    [InlineData(0x2206, false)]
    [InlineData(0x0080, false)]
    public void Fins_response_codes_are_transient_only_for_a_busy_or_timed_out_network(int raw, bool transient)
    {
        var code = new FinsEndCode((ushort)raw);
        var e = new FinsEndCodeException(code, 0x0101, 0);

        e.IsTransient.Should().Be(transient);
        code.IsTransient.Should().Be(transient);
    }

    [Fact]
    public void Timeouts_damaged_frames_and_lost_links_are_transient_and_the_base_is_not()
    {
        new HostLinkTimeoutException("late", TimeSpan.FromSeconds(1)).IsTransient.Should().BeTrue();
        new HostLinkFrameException(FrameError.BadFcs, "damaged").IsTransient.Should().BeTrue();
        new HostLinkConnectionException("gone").IsTransient.Should().BeTrue();
        new HostLinkException("anything").IsTransient.Should().BeFalse();
    }

    [Fact]
    public async Task A_silent_plc_gives_a_transient_timeout()
    {
        var (client, plc) = Connect(_ => null, TimeSpan.FromMilliseconds(150));
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkTimeoutException>();
        e.Which.IsTransient.Should().BeTrue();
    }

    [Fact]
    public async Task A_damaged_answer_is_transient()
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply("@00RD00000AFFFF800000*\r") : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkFrameException>();
        e.Which.Error.Should().Be(FrameError.BadFcs);
        e.Which.IsTransient.Should().BeTrue();
    }

    [Theory]
    [InlineData("13", true)]
    [InlineData("15", false)]
    public async Task An_end_code_answer_is_transient_when_it_reports_line_damage(string code, bool transient)
    {
        var (client, plc) = Connect(f => f == RdD100x3 ? new Reply(TestFrames.Final("@00RD" + code)) : null);
        await using var _ = plc;
        await using var __ = client;

        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 3)).Should().ThrowAsync<HostLinkEndCodeException>();
        e.Which.IsTransient.Should().Be(transient);
    }

    /// <summary>A client and a scripted PLC; the allowance is short only where the PLC stays silent.</summary>
    private static (HostLinkClient Client, ScriptedPlc Plc) Connect(Func<string, Reply?> handler, TimeSpan? allowance = null)
    {
        (Stream host, Stream plc) = InMemoryLink.CreatePair();
        var options = new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = allowance ?? Allowances.LosslessLine,
            ReadRetries = 0,
        };
        return (HostLinkClient.ForStream(host, options), new ScriptedPlc(plc, handler));
    }
}
