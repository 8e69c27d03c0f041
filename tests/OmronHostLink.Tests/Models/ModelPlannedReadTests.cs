using OmronHostLink.Planning;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// Planned reads (<c>ReadTagsAsync</c>) against a model: the planner's reads are checked like single reads, so no FINS
/// and no QQ go to a model without them, and no tag beyond the model's memory is sent.
/// </summary>
public sealed class ModelPlannedReadTests
{
    // Scattered words, so that QQ is cheaper than area reads where it is allowed (UseCompoundRead).
    private static readonly string[] Scattered = [.. Enumerable.Range(0, 40).Select(i => $"D{i * 20}")];

    [Fact]
    public async Task A_model_without_QQ_is_read_by_area_even_with_compound_reads_on()
    {
        // W614 p14-40: the CP2E lists no QQ.
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CP2E" });
        for (int i = 0; i < Scattered.Length; i++)
        {
            plc.WriteWord(PlcArea.Dm, i * 20, (ushort)(i + 1));
        }

        await using var line = EmulatedLine.Start(plc, "CP2E", configure: o => o.UseCompoundRead = CompoundReadMode.On);

        PlcTagValue[] values = await line.Client.ReadTagsAsync(Scattered);

        values.Select(v => (ushort)v.Value).Should().Equal(Enumerable.Range(1, Scattered.Length).Select(i => (ushort)i));
        line.SentFrames.Should().NotContain(f => f.StartsWith("@00QQ", StringComparison.Ordinal));
    }

    [Fact]
    public async Task A_model_with_QQ_is_read_with_it_when_compound_reads_are_on()
    {
        // CQM1/CPM1 manual p388: the CPM1A has QQ.
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc.WriteWord(PlcArea.Dm, 780, 0x0780);
        await using var line = EmulatedLine.Start(plc, "CPM1A", configure: o => o.UseCompoundRead = CompoundReadMode.On);

        PlcTagValue[] values = await line.Client.ReadTagsAsync(Scattered);

        values[^1].Value.Should().Be((ushort)0x0780);
        line.SentFrames.Should().Contain(f => f.StartsWith("@00QQIR", StringComparison.Ordinal));
    }

    [Fact]
    public async Task A_planned_read_with_FINS_on_a_model_without_FINS_is_refused_before_the_wire()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "C200HS" });
        await using var line = EmulatedLine.Start(plc, "C200HS", configure: o => o.CommandSet = HostLinkCommandSet.Fins);

        await FluentActions.Awaiting(() => line.Client.ReadTagsAsync(["D0", "D10", "H5"])).Should().ThrowAsync<NotSupportedException>()
            .WithMessage("A C200HS does not take FINS*");
        line.BytesSent.Should().Be(0);
    }

    [Fact]
    public async Task A_tag_beyond_the_models_memory_is_refused_before_the_wire()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        await using var line = EmulatedLine.Start(plc, "CPM1A");

        await FluentActions.Awaiting(() => line.Client.ReadTagsAsync(["D0", "D1024", "D6144"])).Should().ThrowAsync<ArgumentOutOfRangeException>()
            .WithMessage("*D1024 is beyond the DM area of a CPM1/CPM1A*");
        line.BytesSent.Should().Be(0);
    }
}
