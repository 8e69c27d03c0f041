using System.Collections.Concurrent;
using System.Text;
using FluentAssertions;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;
using Xunit;

namespace OmronHostLink.Tests.Client;

/// <summary>QQ through the client: registered once per unit and tag set, read with QQIR, registered again after end code 19.</summary>
public sealed class CompoundReadTests : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly VirtualPlc _plc = new(new VirtualPlcOptions { Units = [0, 1] });
    private readonly Task _session;
    private readonly HostLinkClient _client;
    private readonly ConcurrentQueue<string> _sent = new();

    public CompoundReadTests()
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _session = _plc.RunAsync(plcEnd, _stop.Token);
        _client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = InProcessLine.InMemoryAllowance });
        _client.FrameObserver = (sent, frame) =>
        {
            if (sent)
            {
                _sent.Enqueue(Encoding.ASCII.GetString(frame.Span));
            }
        };
        _plc.WriteWord(PlcArea.Dm, 100, 0x1111);
        _plc.WriteWord(PlcArea.Dm, 5000, 0x2222);
        _plc.WriteWord(PlcArea.Holding, 7, 0x0080);
        _plc.WriteWord(PlcArea.Timer, 3, 0x0042);
    }

    private int Sent(string start) => _sent.Count(f => f.StartsWith(start, StringComparison.Ordinal));

    [Fact]
    public async Task Registers_once_then_reads_with_QQIR_alone()
    {
        string[] tags = ["D100", "D5000", "H7.07", "T3"];
        (await _client.ReadCompoundAsync(tags)).Should().Equal(0x1111, 0x2222, 1, 0x0042);
        _plc.WriteWord(PlcArea.Dm, 5000, 0x3333);
        (await _client.ReadCompoundAsync(tags)).Should().Equal(0x1111, 0x3333, 1, 0x0042);

        Sent("@00QQMR").Should().Be(1);
        Sent("@00QQIR").Should().Be(2);
    }

    [Fact]
    public async Task A_bit_of_DM_is_read_through_its_word()
    {
        (await _client.ReadCompoundAsync(["D100.04", "D100.05", "H7.07"])).Should().Equal(1, 0, 1);
        _sent.Should().Contain(f => f.StartsWith("@00QQMRDM  0100CH,DM  0100CH,HR  000707", StringComparison.Ordinal));
    }

    [Fact]
    public async Task A_PLC_that_lost_the_registration_is_registered_again_once()
    {
        string[] tags = ["D100", "D5000"];
        await _client.ReadCompoundAsync(tags);
        _plc.Restart();

        (await _client.ReadCompoundAsync(tags)).Should().Equal(0x1111, 0x2222);

        Sent("@00QQMR").Should().Be(2);
        Sent("@00QQIR").Should().Be(3); // read, 19, read again
    }

    [Fact]
    public async Task Another_tag_set_takes_the_units_turn_and_each_unit_keeps_its_own()
    {
        string[] a = ["D100"];
        string[] b = ["D5000"];
        (await _client.ReadCompoundAsync(a)).Should().Equal(0x1111);
        (await _client.ReadCompoundAsync(b)).Should().Equal(0x2222);
        (await _client.ReadCompoundAsync(a)).Should().Equal(0x1111);
        Sent("@00QQMR").Should().Be(3);

        HostLinkUnit other = _client.Unit(1);
        (await other.ReadCompoundAsync(b)).Should().Equal(0x2222);
        (await _client.ReadCompoundAsync(a)).Should().Equal(0x1111);
        (await other.ReadCompoundAsync(b)).Should().Equal(0x2222);
        Sent("@00QQMR").Should().Be(3);
        Sent("@01QQMR").Should().Be(1);
    }

    [Fact]
    public async Task Concurrent_tag_sets_on_one_unit_never_read_through_each_others_registration()
    {
        string[] a = ["D100", "D5000"];
        string[] b = ["D5000", "D100"];
        var reads = new List<Task<ushort[]>>();
        for (int i = 0; i < 20; i++)
        {
            reads.Add(_client.ReadCompoundAsync(i % 2 == 0 ? a : b));
        }

        ushort[][] results = await Task.WhenAll(reads);
        for (int i = 0; i < results.Length; i++)
        {
            results[i].Should().Equal(i % 2 == 0 ? new ushort[] { 0x1111, 0x2222 } : new ushort[] { 0x2222, 0x1111 });
        }
    }

    [Fact]
    public async Task A_units_compound_read_waits_for_the_line_in_its_turn_not_for_another_units()
    {
        // Unit 0's QQIR holds the line (its answer held back); then unit 1 asks for a QQIR, and after it for an RD. The
        // line takes them in the order they asked: unit 1's registration is its own, so its QQIR does not wait for unit
        // 0's to end before it asks for the line (which would let the later RD go first).
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = [0, 1] });
        plc.WriteWord(PlcArea.Dm, 100, 0x1111);
        plc.WriteWord(PlcArea.Dm, 5000, 0x2222);
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        var answers = new HeldAnswers(plcEnd);
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(answers, stop.Token);
        var sent = new ConcurrentQueue<string>();
        await using HostLinkClient client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = InProcessLine.InMemoryAllowance });
        client.FrameObserver = (isSent, frame) =>
        {
            if (isSent)
            {
                sent.Enqueue(Encoding.ASCII.GetString(frame.Span)[..7]);
            }
        };
        HostLinkUnit other = client.Unit(1);
        (await client.ReadCompoundAsync(["D100"])).Should().Equal(0x1111);
        (await other.ReadCompoundAsync(["D5000"])).Should().Equal(0x2222);
        sent.Clear();

        answers.Hold();
        Task<ushort[]> first = client.ReadCompoundAsync(["D100"]);
        await Eventually.UntilAsync(() => sent.Contains("@00QQIR"), "unit 0's QQIR is on the line");
        Task<ushort[]> second = other.ReadCompoundAsync(["D5000"]);
        Task<ushort[]> third = other.ReadWordsAsync("D100", 1);
        answers.Release();

        (await first).Should().Equal(0x1111);
        (await second).Should().Equal(0x2222);
        (await third).Should().Equal(0x1111);
        sent.Should().Equal("@00QQIR", "@01QQIR", "@01RD01");
        await stop.CancelAsync();
        await session;
    }

    [Fact]
    public async Task Bad_input_is_refused_before_anything_is_sent()
    {
        await FluentActions.Awaiting(() => _client.ReadCompoundAsync(Array.Empty<string>())).Should().ThrowAsync<ArgumentException>();
        await FluentActions.Awaiting(() => _client.ReadCompoundAsync(Enumerable.Range(0, 129).Select(i => $"D{i}").ToArray())).Should().ThrowAsync<ArgumentException>();
        await FluentActions.Awaiting(() => _client.ReadCompoundAsync(["W3"])).Should().ThrowAsync<ArgumentException>();
        _sent.Should().BeEmpty();
    }

    [Fact]
    public void A_reopened_link_holds_no_registration()
    {
        var registry = new CompoundReadRegistry();
        CompoundItem[] items = [CompoundItem.ForWord(CompoundArea.Dm, 1)];
        registry.Registered(0, items, openings: 1);
        registry.Holds(0, items, openings: 1).Should().BeTrue();
        registry.Holds(0, items, openings: 2).Should().BeFalse();
        registry.Holds(1, items, openings: 1).Should().BeFalse();
        registry.Holds(0, [CompoundItem.ForWord(CompoundArea.Dm, 2)], openings: 1).Should().BeFalse();
    }

    /// <summary>The PLC's end of the line, whose answers can be held back until released.</summary>
    private sealed class HeldAnswers(Stream inner) : PassThroughStream(inner)
    {
        private volatile TaskCompletionSource? _held;

        public void Hold() => _held = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);

        public void Release() => _held?.TrySetResult();

        public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            if (_held is { } held)
            {
                await held.Task.WaitAsync(cancellationToken).ConfigureAwait(false);
            }

            await Inner.WriteAsync(buffer, cancellationToken).ConfigureAwait(false);
        }
    }

    public async ValueTask DisposeAsync()
    {
        await _client.DisposeAsync();
        await _stop.CancelAsync();
        await _session;
        _stop.Dispose();
    }
}
