using System.Diagnostics;
using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Faults;

namespace OmronHostLink.Simulator.Tests;

/// <summary>Each fault option produces the fault it names, deterministically for a seed.</summary>
public class FaultInjectionTests
{
    private static readonly string Ms = RawHost.Command("@00MS");
    private static readonly string MsAnswer = RawHost.Command("@00MS0000B0");

    private static RawHost Start(FaultOptions faults) => RawHost.Start(new VirtualPlcOptions { Faults = faults });

    [Fact]
    public async Task Drop_sends_no_answer()
    {
        await using RawHost host = Start(new FaultOptions { Drop = 1 });
        await host.SendAsync(Ms);
        await host.ExpectSilenceAsync();
        host.Plc.FaultCounters.Dropped.Should().Be(1);
        host.Plc.FaultCounters.Total.Should().Be(1);
    }

    [Fact]
    public async Task Corrupt_changes_one_character_so_the_FCS_fails()
    {
        await using RawHost host = Start(new FaultOptions { Corrupt = 1, Seed = 3 });
        for (int i = 0; i < 5; i++)
        {
            string frame = await host.TransactAsync(RawHost.Command("@00RD00000004"));
            string good = RawHost.Command("@00RD000000000000000000");
            frame.Length.Should().Be(good.Length);
            Enumerable.Range(0, good.Length).Count(k => frame[k] != good[k]).Should().Be(1);
            frame.Should().StartWith("@").And.EndWith("*\r");
            FluentActions.Invoking(() => FrameParser.ParseFirst(Encoding.ASCII.GetBytes(frame)))
                .Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.BadFcs);
        }

        host.Plc.FaultCounters.Corrupted.Should().Be(5);
    }

    [Fact]
    public async Task Noise_puts_bytes_before_the_frame()
    {
        await using RawHost host = Start(new FaultOptions { Noise = 1 });
        string got = await host.TransactAsync(Ms);
        int at = got.IndexOf('@', StringComparison.Ordinal);
        at.Should().BeInRange(1, 8);
        got[at..].Should().Be(MsAnswer);
        got[..at].Should().NotContain("\r");
        host.Plc.FaultCounters.Noise.Should().Be(1);
    }

    [Fact]
    public async Task Truncate_cuts_the_frame_before_its_CR()
    {
        await using RawHost host = Start(new FaultOptions { Truncate = 1 });
        await host.SendAsync(Ms);
        string got = await host.ReadUntilQuietAsync(TimeSpan.FromMilliseconds(200));
        got.Should().NotBeEmpty().And.NotContain("\r");
        MsAnswer.Should().StartWith(got);
        host.Plc.FaultCounters.Truncated.Should().Be(1);
    }

    [Fact]
    public async Task Late_answers_after_the_hosts_deadline()
    {
        await using RawHost host = Start(new FaultOptions { Late = 1, LateBy = TimeSpan.FromMilliseconds(400) });
        var clock = Stopwatch.StartNew();
        await host.SendAsync(Ms);
        await FluentActions.Awaiting(() => host.ReadFrameAsync(TimeSpan.FromMilliseconds(150))).Should().ThrowAsync<TimeoutException>();
        (await host.ReadFrameAsync()).Should().Be(MsAnswer, "the stale answer still comes");
        clock.Elapsed.Should().BeGreaterThanOrEqualTo(TimeSpan.FromMilliseconds(390));
        host.Plc.FaultCounters.Late.Should().Be(1);
    }

    [Fact]
    public async Task Echo_sends_the_command_back_before_the_answer()
    {
        await using RawHost host = Start(new FaultOptions { Echo = 1 });
        (await host.TransactAsync(Ms)).Should().Be(Ms);
        (await host.ReadFrameAsync()).Should().Be(MsAnswer);
        host.Plc.FaultCounters.Echoed.Should().Be(1);
    }

    [Fact]
    public async Task The_bare_CR_of_the_command_handshake_is_never_faulted()
    {
        await using RawHost host = Start(new FaultOptions { Drop = 1 });
        (await host.TransactAsync(RawHost.Delimited("@00WD00000001"))).Should().Be("\r");
        await host.SendAsync(RawHost.Command("0002"));
        await host.ExpectSilenceAsync();
        host.Plc.ReadWords(PlcArea.Dm, 0, 2).Should().Equal(1, 2);
    }

    [Fact]
    public async Task The_same_seed_gives_the_same_faults()
    {
        var faults = new FaultOptions { Seed = 7, Drop = 0.2, Corrupt = 0.2, Noise = 0.2, Truncate = 0.2, Late = 0.2, LateBy = TimeSpan.FromMilliseconds(30), Echo = 0.2 };
        (string transcript, string counters) first = await RunScriptAsync(faults);
        (string transcript, string counters) second = await RunScriptAsync(faults);
        second.Should().Be(first);
        first.counters.Should().NotContain("dropped 0,").And.NotContain("corrupted 0,");

        faults.Seed = 8;
        (await RunScriptAsync(faults)).transcript.Should().NotBe(first.transcript);
    }

    private static async Task<(string transcript, string counters)> RunScriptAsync(FaultOptions faults)
    {
        await using RawHost host = Start(faults);
        var transcript = new StringBuilder();
        for (int i = 0; i < 16; i++)
        {
            await host.SendAsync(RawHost.Command($"@00RD{i:D4}0002"));
            transcript.Append(await host.ReadUntilQuietAsync(TimeSpan.FromMilliseconds(20)));

            // Start every command from a clean line, as a host resynchronises after a failed exchange.
            await host.SendAsync("@**\r");
        }

        // The session answers in order, so the whole byte stream is deterministic; only where the pauses fall is not.
        transcript.Append(await host.ReadUntilQuietAsync(TimeSpan.FromMilliseconds(300)));
        return (transcript.ToString(), host.Plc.FaultCounters.ToString());
    }
}
