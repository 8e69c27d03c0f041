using OmronHostLink.Transports;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Tests.Planning;

/// <summary>ReadTagsAsync against the simulator over an in-memory link, both protocols, two units.</summary>
public sealed class ReadTagsTests
{
    [Theory]
    [InlineData(HostLinkCommandSet.CMode)]
    [InlineData(HostLinkCommandSet.Fins)]
    public async Task ReadMany_returns_every_tag_from_the_right_unit(HostLinkCommandSet protocol)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Units = new[] { 0, 5 } });
        for (int i = 0; i < 2000; i++)
        {
            plc.WriteWord(PlcArea.Dm, i, (ushort)(i * 7));
        }

        plc.WriteWord(PlcArea.Holding, 10, 0x0008);
        plc.WriteWords(PlcArea.Dm, 3000, PlcWords.FromString("AB"));
        var f = new ushort[2];
        PlcWords.WriteSingle(2.25f, f);
        plc.WriteWords(PlcArea.Em, 50, f, bank: 1);
        plc.WriteWord(PlcArea.Counter, 12, 0x0042);

        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        await using HostLinkClient client = HostLinkClient.ForStream(host, new HostLinkClientOptions { CommandSet = protocol, LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine });

        var tags = new[]
        {
            new PlcTag("D5"), new PlcTag("D9"), new PlcTag("D1500", PlcValueType.Int16), new PlcTag("H10.03", PlcValueType.Bit),
            new PlcTag("E1_50", PlcValueType.Float), new PlcTag("C12"), new PlcTag("D7", unit: 5), new PlcTag("D3000"),
        };
        PlcTagValue[] values = await client.ReadTagsAsync(tags);
        values.Select(v => v.Value).Should().Equal((ushort)35, (ushort)63, unchecked((short)10500), true, 2.25f, (ushort)0x42, (ushort)49, (ushort)0x4142);
        values.Select(v => v.Tag).Should().Equal(tags);

        stop.Cancel();
        await session;
    }

    [Theory]
    [InlineData(HostLinkCommandSet.CMode)]
    [InlineData(HostLinkCommandSet.Fins)]
    public async Task Completion_flags_and_present_values_of_the_same_timers_are_told_apart(HostLinkCommandSet protocol)
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Timer, 5, 0x0123);
        plc.SetFlag(PlcArea.Timer, 5, true);
        plc.SetFlag(PlcArea.Timer, 8, true);
        plc.SetFlag(PlcArea.Counter, 7, true);

        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        await using HostLinkClient client = HostLinkClient.ForStream(host, new HostLinkClientOptions { CommandSet = protocol, LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine });

        PlcTagValue[] values = await client.ReadTagsAsync(new[] { "T5:bit", "T5", "T6:bit", "T8:bit", "C7:bit", "C8:bit" });
        values.Select(v => v.Value).Should().Equal(true, (ushort)0x0123, false, true, true, false);

        stop.Cancel();
        await session;
    }

    [Fact]
    public async Task A_plan_is_made_once_and_executed_many_times()
    {
        var plc = new VirtualPlc();
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        Task session = plc.RunAsync(plcEnd, stop.Token);
        await using HostLinkClient client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine });
        ReadPlan plan = new ReadPlanner().Plan(new[] { new PlcTag("D0"), new PlcTag("D2") });
        for (ushort i = 0; i < 3; i++)
        {
            plc.WriteWord(PlcArea.Dm, 2, i);
            (await client.ReadTagsAsync(plan))[1].Value.Should().Be(i);
        }

        stop.Cancel();
        await session;
    }

    [Fact]
    public async Task Nothing_is_sent_when_a_tag_cannot_be_read_with_the_protocol()
    {
        int frames = 0;
        (Stream host, _) = InMemoryLink.CreatePair();
        await using HostLinkClient client = HostLinkClient.ForStream(host);
        client.FrameObserver = (_, _) => frames++;
        await FluentActions.Awaiting(async () => await client.ReadTagsAsync(new[] { new PlcTag("W0") })).Should().ThrowAsync<ArgumentException>();
        frames.Should().Be(0);
    }
}
