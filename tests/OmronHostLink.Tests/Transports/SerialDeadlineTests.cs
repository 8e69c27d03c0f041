using System.Diagnostics;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>
/// On Windows <c>SerialPort.BaseStream.ReadAsync</c> ignores its cancellation token. Over a real pty whose reads are
/// made to ignore cancellation the same way, the link's deadlines still hold (its pump never cancels a read), and
/// closing the client closes the port, which ends the read left pending.
/// </summary>
[Trait("Category", "Slow")]
public sealed class SerialDeadlineTests
{
    // The read left pending never completes by itself (the line is silent and it ignores its token): finishing at all
    // shows the deadline and the close did not wait for it. The bounds leave room for a loaded machine.
    private static readonly TimeSpan Prompt = TimeSpan.FromSeconds(3);
    private static readonly TimeSpan Slack = TimeSpan.FromSeconds(2);

    private static HostLinkClientOptions Options => new()
    {
        TurnaroundAllowance = TimeSpan.FromMilliseconds(100),
        ReadRetries = 0,
    };

    [Fact]
    public async Task A_silent_line_times_out_on_time_though_reads_ignore_cancellation_and_closing_ends_the_pending_read()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var settings = new SerialLineSettings { PortName = pair.PathA, BaudRate = 115200 };
        var line = new CancellationIgnoringStream(await SocatPtyPair.OpenAsync(pair.PathA));
        var port = new FakeSerialPort(pair.PathA, line);
        using Stream silentPlc = await SocatPtyPair.OpenAsync(pair.PathB);

        HostLinkClient client = HostLinkClient.Create(new SerialTransport(settings, _ => port), Options);
        var clock = Stopwatch.StartNew();
        var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();
        clock.Elapsed.Should().BeLessThan(e.Which.Timeout + Slack, "the deadline does not wait for the stream read");
        line.IgnoredTokens.Should().BePositive("the pump's read was given a token the stream ignored");
        Task pending = line.LastRead!;
        pending.IsCompleted.Should().BeFalse("the read ignores cancellation and nothing arrived");

        await client.DisposeAsync().AsTask().WaitAsync(Prompt);
        Exception? error = await Record.ExceptionAsync(() => pending.WaitAsync(Prompt));
        pending.IsCompleted.Should().BeTrue("closing the client closed the port, which ends the read");
        error.Should().BeAssignableTo<ObjectDisposedException>("the port was closed under the read");
        port.Disposed.Should().BeTrue();
    }

    [Fact]
    public async Task After_a_timeout_the_link_resynchronises_and_reads_correctly_over_such_a_stream()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        var settings = new SerialLineSettings { PortName = pair.PathA, BaudRate = 115200 };
        var port = new FakeSerialPort(pair.PathA, new CancellationIgnoringStream(await SocatPtyPair.OpenAsync(pair.PathA)));
        // An allowance a busy machine's simulator keeps to once it answers; the first read still times out.
        HostLinkClientOptions options = Options;
        options.TurnaroundAllowance = TimeSpan.FromSeconds(1);
        await using HostLinkClient client = HostLinkClient.Create(new SerialTransport(settings, _ => port), options);

        // Nobody answers at first.
        await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkTimeoutException>();

        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Dm, 0, [0x1234, 0x5678]);
        await using var host = new SerialSimulatorHost(plc, new SerialLineSettings { PortName = pair.PathB });
        await host.StartAsync();
        (await client.ReadWordsAsync("D0", 2)).Should().Equal(0x1234, 0x5678);
    }

    /// <summary>A stream whose reads, like Windows serial reads, go on whatever their token says.</summary>
    private sealed class CancellationIgnoringStream(Stream inner) : PassThroughStream(inner)
    {
        private int _ignored;

        public int IgnoredTokens => Volatile.Read(ref _ignored);

        public Task<int>? LastRead { get; private set; }

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            if (cancellationToken.CanBeCanceled)
            {
                Interlocked.Increment(ref _ignored);
            }

            Task<int> read = Inner.ReadAsync(buffer, CancellationToken.None).AsTask();
            LastRead = read;
            return new ValueTask<int>(read);
        }
    }
}
