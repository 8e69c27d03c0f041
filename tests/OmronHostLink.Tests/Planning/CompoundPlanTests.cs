using System.Collections.Concurrent;
using System.Text;
using FluentAssertions;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;
using Xunit;

namespace OmronHostLink.Tests.Planning;

/// <summary>The planner's use of QQ for C-mode: one registered QQIR per unit where it costs fewer characters a cycle.</summary>
public sealed class CompoundPlanTests : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly VirtualPlc _plc = new(new VirtualPlcOptions { Units = [0, 1] });
    private readonly Task _session;
    private readonly HostLinkClient _client;
    private readonly ConcurrentQueue<string> _sent = new();

    public CompoundPlanTests()
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _session = _plc.RunAsync(plcEnd, _stop.Token);
        _client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = InProcessLine.InMemoryAllowance, UseCompoundRead = CompoundReadMode.On });
        _client.FrameObserver = (sent, frame) =>
        {
            if (sent)
            {
                _sent.Enqueue(Encoding.ASCII.GetString(frame.Span));
            }
        };
        for (int i = 0; i < 10000; i++)
        {
            _plc.WriteWord(PlcArea.Dm, i, (ushort)(i * 7));
        }
    }

    private static PlcTag[] Isolated(int count, int unit = 0, int step = 50)
        => Enumerable.Range(0, count).Select(i => new PlcTag($"D{i * step}", PlcValueType.Word, unit == 0 ? null : unit)).ToArray();

    private int Sent(string start) => _sent.Count(f => f.StartsWith(start, StringComparison.Ordinal));

    [Fact]
    public void Scattered_words_go_into_one_QQIR_per_unit_where_it_is_cheaper()
    {
        PlcTag[] tags = [.. Isolated(20), .. Isolated(10, unit: 1), new PlcTag("T5", PlcValueType.Word, null)];
        ReadPlan areas = new ReadPlanner { UseCompoundRead = CompoundReadMode.Off }.Plan(tags);
        ReadPlan plan = new ReadPlanner { UseCompoundRead = CompoundReadMode.On }.Plan(tags);

        // The timer's PV is one more item of unit 0's QQIR (its flag and PV: five characters instead of an RC read).
        plan.Reads.Select(r => (r.Kind, r.Unit, r.Count)).Should().Equal((PlannedReadKind.CModeCompound, 0, 21), (PlannedReadKind.CModeCompound, 1, 10));
        plan.Reads[0].Items.Should().Contain(PlcAddress.Parse("T5"));
        plan.Characters.Should().BeLessThan(areas.Characters);
        plan.Reads[1].Characters.Should().Be(ReadPlanner.CompoundReadCharacters(10, out _));
        plan.Reads[0].Characters.Should().Be(ReadPlanner.CompoundReadCharacters(21, out _) + 1, "a PV answers with its completion flag first");
    }

    [Fact]
    public void A_word_only_bit_tags_need_is_registered_as_its_bits_where_QQ_reads_bits()
    {
        PlcTag[] tags =
        [
            .. Isolated(10),
            PlcTag.Parse("CIO100.03:bit"), PlcTag.Parse("H200.15:bit"), // bits alone: one character each
            PlcTag.Parse("H300.01:bit"), PlcTag.Parse("H300:word"), // the word is read anyway
            PlcTag.Parse("A400.00:bit"), PlcTag.Parse("A400.01:bit"), PlcTag.Parse("A400.02:bit"), // three bits: the word is shorter
            PlcTag.Parse("D9000.04:bit"), // DM is read by words
        ];

        PlannedRead qq = new ReadPlanner { UseCompoundRead = CompoundReadMode.On }.Plan(tags).Reads.Should().ContainSingle().Which;

        qq.Kind.Should().Be(PlannedReadKind.CModeCompound);
        qq.Items.Where(a => a.IsBit).Should().BeEquivalentTo([PlcAddress.Parse("CIO100.03"), PlcAddress.Parse("H200.15")]);
        qq.Items.Should().Contain([PlcAddress.Parse("H300"), PlcAddress.Parse("A400"), PlcAddress.Parse("D9000")]);
        qq.Count.Should().Be(15);
    }

    [Fact]
    public async Task Bits_and_PVs_read_with_QQ_decode_as_their_area_reads_do()
    {
        _plc.WriteWord(PlcArea.Cio, 100, 0x0008);
        _plc.WriteWord(PlcArea.Holding, 200, 0x7FFF);
        _plc.WriteWord(PlcArea.Holding, 300, 0x0002);
        _plc.WriteWord(PlcArea.Auxiliary, 400, 0x0005);
        _plc.WriteWord(PlcArea.Timer, 5, 0x0123);
        PlcTag[] tags =
        [
            .. Isolated(10),
            PlcTag.Parse("CIO100.03:bit"), PlcTag.Parse("H200.15:bit"), PlcTag.Parse("H300.01:bit"), PlcTag.Parse("H300:word"),
            PlcTag.Parse("A400.00:bit"), PlcTag.Parse("A400.01:bit"), PlcTag.Parse("A400.02:bit"), PlcTag.Parse("D9000.04:bit"),
            new PlcTag("T5", PlcValueType.Word, null),
        ];

        PlcTagValue[] byQq = await _client.ReadTagsAsync(tags);
        PlcTagValue[] byArea = await _client.ReadTagsAsync(new ReadPlanner(HostLinkCommandSet.CMode, _client.LineTiming) { UseCompoundRead = CompoundReadMode.Off }.Plan(tags));

        Sent("@00QQIR").Should().Be(1);
        byQq.Select(v => v.Value).Should().Equal(byArea.Select(v => v.Value));
        byQq.Skip(10).Select(v => v.Value).Should().Equal(true, false, true, (ushort)2, true, false, true, true, (ushort)0x0123); // D9000 = 63000 = F618 hex
    }

    [Fact]
    public void A_dense_range_keeps_its_area_read_and_the_option_turns_QQ_off()
    {
        PlcTag[] dense = Enumerable.Range(0, 30).Select(i => new PlcTag($"D{i}", PlcValueType.Word)).ToArray();
        new ReadPlanner { UseCompoundRead = CompoundReadMode.On }.Plan(dense).Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.CModeArea);
        new ReadPlanner { UseCompoundRead = CompoundReadMode.Off }.Plan(Isolated(20)).Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.CModeArea);
        new ReadPlanner(HostLinkCommandSet.Fins).Plan(Isolated(20)).Reads.Should().NotContain(r => r.Kind == PlannedReadKind.CModeCompound);
    }

    [Fact]
    public void Beyond_128_words_the_dearest_go_to_QQ_and_the_rest_to_area_reads()
    {
        ReadPlan plan = new ReadPlanner { UseCompoundRead = CompoundReadMode.On }.Plan(Isolated(150, step: 60));
        plan.Reads.Should().ContainSingle(r => r.Kind == PlannedReadKind.CModeCompound).Which.Count.Should().Be(128);
        plan.Reads.Where(r => r.Kind == PlannedReadKind.CModeArea).Sum(r => r.Count).Should().BeGreaterThanOrEqualTo(22);
    }

    [Fact]
    public async Task ReadTagsAsync_registers_once_and_returns_what_area_reads_return()
    {
        PlcTag[] tags = [.. Isolated(40), .. Isolated(15, unit: 1), PlcTag.Parse("D300:int32")];
        PlcTagValue[] first = await _client.ReadTagsAsync(tags);
        PlcTagValue[] second = await _client.ReadTagsAsync(tags);
        PlcTagValue[] byArea = await _client.ReadTagsAsync(new ReadPlanner(HostLinkCommandSet.CMode, _client.LineTiming) { UseCompoundRead = CompoundReadMode.Off }.Plan(tags));

        first.Select(v => v.Value).Should().Equal(byArea.Select(v => v.Value));
        second.Select(v => v.Value).Should().Equal(byArea.Select(v => v.Value));
        Sent("@00QQMR").Should().Be(1);
        Sent("@01QQMR").Should().Be(1);
        Sent("@00QQIR").Should().Be(2);
        Sent("@01QQIR").Should().Be(2);
    }

    [Fact]
    public async Task A_watch_registers_once_and_again_after_the_PLC_restarts()
    {
        PlcTag[] tags = Isolated(20);
        int polled = 0;
        await foreach (WatchEvent e in _client.WatchAsync(tags, new WatchOptions { Interval = TimeSpan.Zero, ReportEveryCycle = true }))
        {
            if (e.Kind != WatchEventKind.Polled)
            {
                continue;
            }

            if (++polled == 3)
            {
                _plc.Restart();
            }

            if (polled == 5)
            {
                break;
            }
        }

        Sent("@00QQMR").Should().Be(2);
        Sent("@00QQIR").Should().Be(6); // five cycles and the one answered 19
        _sent.Should().NotContain(f => f.StartsWith("@00RD", StringComparison.Ordinal));
    }

    [Fact]
    public async Task Another_tag_set_on_the_unit_reads_by_area_when_taking_the_turn_costs_more()
    {
        PlcTag[] a = Isolated(20);
        PlcTag[] b = [new PlcTag("D7001", PlcValueType.Word), new PlcTag("D8001", PlcValueType.Word)];
        new ReadPlanner { UseCompoundRead = CompoundReadMode.On }.Plan(b).Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.CModeCompound);

        await _client.ReadTagsAsync(a);
        (await _client.ReadTagsAsync(b)).Select(v => v.Value).Should().Equal((ushort)(7001 * 7), (ushort)(8001 * 7));
        await _client.ReadTagsAsync(a);

        Sent("@00QQMR").Should().Be(1); // b did not take a's registration: two RDs cost less than QQMR + QQIR
        Sent("@00RD").Should().Be(2);
    }

    public async ValueTask DisposeAsync()
    {
        await _client.DisposeAsync();
        await _stop.CancelAsync();
        await _session;
        _stop.Dispose();
    }
}
