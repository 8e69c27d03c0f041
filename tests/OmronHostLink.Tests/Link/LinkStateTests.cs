using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Link;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Link;

/// <summary>The link's <see cref="LinkState"/> through each transition, driven by a scripted PLC and a fake clock.</summary>
public sealed class LinkStateTests
{
    private const string Ms = "@00MS5E*\r";
    private const string Rd40 = "@00RD0000004052*\r"; // c_rd_multi_response_40w's command
    private static readonly LineTiming Timing = new(115200, 11);
    private static readonly TimeSpan Allowance = TimeSpan.FromMilliseconds(150);
    private static readonly string MsAnswer = TestFrames.Final("@00MS00" + "0000");

    private enum Plc
    {
        Answers,
        Silent,
        FirstFrameOnly,
    }

    private static HostLinkRequest Request(CModeCommand command) => new(0, command.Header, command.ToMessage(0), command.Exchange);

    private static ValueTask<int> Run(HostLinkConnection link, CModeCommand command, CancellationToken cancellationToken = default)
        => link.ExecuteAsync(Request(command), 0, static (text, _) => text.Length, 0, cancellationToken);

    [Fact]
    public Task Every_transition() => Task.Run(async () =>
    {
        var time = new FakeTimeProvider();
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        var link = new HostLinkConnection(new StreamTransport(host), new HostLinkConnectionOptions { LineTiming = Timing, TurnaroundAllowance = Allowance, TimeProvider = time });
        var mode = Plc.Answers;
        await using var plc = new ScriptedPlc(plcEnd, f => mode switch
        {
            Plc.Answers when f == Ms => new Reply(MsAnswer),
            Plc.FirstFrameOnly when f == Rd40 => new Reply(GoldenFrames.Rd40Frames[0]),
            Plc.Answers => null, // TS fences are echoed
            _ => Reply.None,
        });

        link.State.Should().Be(LinkState.Closed);
        (await Run(link, CModeCommands.StatusReadCommand)).Should().Be(6);
        link.State.Should().Be(LinkState.Ready, "the first call opened the transport");

        mode = Plc.Silent;
        ValueTask<int> silent = Run(link, CModeCommands.StatusReadCommand);
        time.Advance(TimeSpan.FromSeconds(1));
        await FluentActions.Awaiting(() => silent.AsTask()).Should().ThrowAsync<HostLinkTimeoutException>();
        link.State.Should().Be(LinkState.NeedsResync, "a late answer may still come");

        mode = Plc.Answers;
        (await Run(link, CModeCommands.StatusReadCommand)).Should().Be(6);
        link.State.Should().Be(LinkState.Ready, "the TS fence was echoed");

        mode = Plc.FirstFrameOnly;
        ValueTask<int> cut = Run(link, new AreaReadCommand(CModeArea.Dm, 0, 40));
        await WaitUntil(() => plc.ReceivedCount(f => f == "\r") == 1);
        time.Advance(TimeSpan.FromSeconds(1));
        await FluentActions.Awaiting(() => cut.AsTask()).Should().ThrowAsync<HostLinkTimeoutException>();
        link.State.Should().Be(LinkState.NeedsInitialize, "the PLC still holds the rest of the answer");

        mode = Plc.Answers;
        (await Run(link, CModeCommands.StatusReadCommand)).Should().Be(6);
        link.State.Should().Be(LinkState.Ready);
        plc.Received.Should().Contain("@**\r", "INITIALIZE went before the fence");

        await plcEnd.DisposeAsync();
        await FluentActions.Awaiting(() => Run(link, CModeCommands.StatusReadCommand).AsTask()).Should().ThrowAsync<HostLinkConnectionException>();
        link.State.Should().Be(LinkState.Closed, "a lost stream breaks the link and closes the transport");

        await link.DisposeAsync();
        link.State.Should().Be(LinkState.Disposed);
        await FluentActions.Awaiting(() => Run(link, CModeCommands.StatusReadCommand).AsTask()).Should().ThrowAsync<ObjectDisposedException>();
    });

    /// <summary>Waits for the scripted PLC (which runs on the real clock) to have seen something.</summary>
    private static Task WaitUntil(Func<bool> condition) => Eventually.UntilAsync(condition, "the scripted PLC has seen it");
}
