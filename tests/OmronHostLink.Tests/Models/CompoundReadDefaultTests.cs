using Microsoft.Extensions.Logging;
using OmronHostLink.Planning;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// <see cref="CompoundReadMode.Auto"/>, the default of the client and the planner alike: QQ for a unit whose model lists
/// it (configured, or named by MM, asked once), area reads for the others; a unit that claims QQ and answers it with an
/// end code is read by area from then on, that read included, and the client says so once.
/// </summary>
public sealed class CompoundReadDefaultTests
{
    // Forty isolated words: one QQIR costs far fewer characters than their area reads.
    private static readonly string[] Scattered = [.. Enumerable.Range(0, 40).Select(i => $"D{i * 20}")];

    [Fact]
    public void The_client_and_the_planner_default_to_Auto()
    {
        new HostLinkClientOptions().UseCompoundRead.Should().Be(CompoundReadMode.Auto);
        new ReadPlanner().UseCompoundRead.Should().Be(CompoundReadMode.Auto);
        new HostLinkClientSettings().ToClientOptions().UseCompoundRead.Should().Be(CompoundReadMode.Auto);
    }

    [Theory]
    [InlineData("CS1", CompoundReadMode.Auto, true)]
    [InlineData("CPM1A", CompoundReadMode.Auto, true)]
    [InlineData("C200HS", CompoundReadMode.Auto, true)]
    [InlineData("CP2E", CompoundReadMode.Auto, false)]
    [InlineData("C200H", CompoundReadMode.Auto, false)]
    [InlineData(null, CompoundReadMode.Auto, false)]
    [InlineData(null, CompoundReadMode.On, true)]
    [InlineData("CP2E", CompoundReadMode.On, false)]
    [InlineData("CS1", CompoundReadMode.Off, false)]
    public void The_planner_plans_QQ_by_the_mode_and_the_model(string? model, CompoundReadMode mode, bool qq)
    {
        var planner = new ReadPlanner { UseCompoundRead = mode, Model = model is null ? null : PlcModelProfile.Parse(model) };

        ReadPlan plan = planner.Plan(Scattered.Select(t => PlcTag.Parse(t)).ToArray());

        plan.Reads.Any(r => r.Kind == PlannedReadKind.CModeCompound).Should().Be(qq);
    }

    [Fact]
    public void A_tag_beyond_the_planners_model_is_refused()
    {
        var planner = new ReadPlanner { Model = PlcModelProfile.Parse("CPM1A") };

        FluentActions.Invoking(() => planner.Plan([PlcTag.Parse("D0"), PlcTag.Parse("D1024")])).Should().Throw<ArgumentOutOfRangeException>()
            .WithMessage("*D1024 is beyond the DM area*");
    }

    [Theory]
    [InlineData("CS1")]
    [InlineData("CPM1A")]
    public async Task A_configured_model_with_QQ_is_read_with_it_and_not_asked(string model)
    {
        var plc = Plc(model);
        await using var line = EmulatedLine.Start(plc, model);

        await ReadTwiceAsync(line);

        line.SentFrames.Should().NotContain(f => Header(f) == "MM");
        line.SentFrames.Count(f => f.StartsWith("@00QQMR", StringComparison.Ordinal)).Should().Be(1, "registered once");
        line.SentFrames.Count(f => f.StartsWith("@00QQIR", StringComparison.Ordinal)).Should().Be(2);
    }

    [Theory]
    [InlineData("CP2E")]
    [InlineData("C200H")]
    public async Task A_configured_model_without_QQ_never_gets_one(string model)
    {
        var plc = Plc(model);
        await using var line = EmulatedLine.Start(plc, model);

        await ReadTwiceAsync(line);

        line.SentFrames.Should().NotContain(f => Header(f) == "QQ" || Header(f) == "MM");
    }

    [Theory]
    [InlineData("CS1", true)]
    [InlineData("CPM1A", true)]
    [InlineData("C200H", false)]
    [InlineData("CP2E", false)]
    public async Task Without_a_configured_model_the_unit_is_asked_MM_once(string model, bool qq)
    {
        var plc = Plc(model);
        var logs = new CapturingLoggerProvider();
        using var loggers = LoggerFactory.Create(b => b.AddProvider(logs).SetMinimumLevel(LogLevel.Debug));
        await using var line = EmulatedLine.Start(plc, model: null, configure: o => o.LoggerFactory = loggers);

        await ReadTwiceAsync(line);

        // The CP2E has no MM (W614): it answers IC, and is read by area like a model without QQ.
        line.SentFrames.Count(f => Header(f) == "MM").Should().Be(1);
        line.SentFrames.Any(f => Header(f) == "QQ").Should().Be(qq);
        logs.Entries.Should().ContainSingle(e => e.EventId.Id == 22 || e.EventId.Id == 23).Which.Message.Should().Contain(qq ? "use QQ" : "area reads");
    }

    [Fact]
    public async Task A_unit_that_claims_QQ_and_answers_it_with_IC_is_read_by_area_from_then_on_and_told_once()
    {
        // MM says CS/CJ, which lists QQ; the PLC (or a converter in between) answers QQ with IC.
        var plc = Plc("CS1");
        plc.Options.RefusedCommands = ["QQ"];
        var logs = new CapturingLoggerProvider();
        using var loggers = LoggerFactory.Create(b => b.AddProvider(logs).SetMinimumLevel(LogLevel.Debug));
        await using var line = EmulatedLine.Start(plc, model: null, configure: o => o.LoggerFactory = loggers);

        await ReadTwiceAsync(line);
        await ReadTwiceAsync(line);

        line.SentFrames.Count(f => Header(f) == "QQ").Should().Be(1, "the first QQ answered IC; none is sent after it");
        line.SentFrames.Count(f => Header(f) == "MM").Should().Be(1);
        LogEntry refused = logs.Entries.Should().ContainSingle(e => e.EventId.Id == 24).Which;
        refused.Level.Should().Be(LogLevel.Warning);
        refused.Message.Should().Contain("Unit 00 answered QQ with IC").And.Contain("its model (CS1/CJ1/CJ2) lists QQ").And.Contain("area reads from now on");
    }

    [Fact]
    public async Task A_watch_reports_its_plan_and_plans_again_when_the_model_is_known()
    {
        var plc = Plc("CS1");
        await using var line = EmulatedLine.Start(plc, model: null);
        var plans = new List<ReadPlan>();
        int polls = 0;
        await foreach (WatchEvent e in line.Client.WatchAsync(Scattered.Select(t => PlcTag.Parse(t)).ToArray(), new WatchOptions { Interval = TimeSpan.Zero, ReportEveryCycle = true, ReportPlans = true }))
        {
            if (e.Kind == WatchEventKind.Planned)
            {
                plans.Add(e.Plan!);
            }
            else if (e.Kind == WatchEventKind.Polled && ++polls == 3)
            {
                break;
            }
        }

        // Planned before the first read with what is known (area reads), then with the model MM named once the unit
        // has answered: a silent unit is never asked MM, only read.
        plans.Should().HaveCount(2);
        plans[0].Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.CModeArea);
        plans[1].Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.CModeCompound);
        plans[1].ToString().Should().MatchRegex(@"^1 read \(1 QQIR of 40 items\), \d+ characters, \d+ ms at 115200 bps$");
        line.SentFrames.Count(f => Header(f) == "MM").Should().Be(1);
    }

    [Fact]
    public async Task A_watch_plans_area_reads_after_a_unit_refuses_QQ()
    {
        var plc = Plc("CS1");
        plc.Options.RefusedCommands = ["QQ"];
        await using var line = EmulatedLine.Start(plc, model: null);
        var plans = new List<ReadPlan>();
        var values = new Dictionary<int, PlcValue>();
        int polls = 0;
        await foreach (WatchEvent e in line.Client.WatchAsync(Scattered.Select(t => PlcTag.Parse(t)).ToArray(), new WatchOptions { Interval = TimeSpan.Zero, ReportEveryCycle = true, ReportPlans = true }))
        {
            switch (e.Kind)
            {
                case WatchEventKind.Planned:
                    plans.Add(e.Plan!);
                    break;
                case WatchEventKind.Changed:
                    values[e.TagIndex] = e.NewValue;
                    break;
                case WatchEventKind.Polled:
                    polls++;
                    break;
                default:
                    throw new Xunit.Sdk.XunitException($"Unexpected {e}");
            }

            if (polls == 4)
            {
                break;
            }
        }

        // Area reads until the unit answered and MM named its model; QQ, refused with IC; area reads again.
        plans.Should().HaveCount(3);
        plans[0].Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.CModeArea);
        plans[1].Reads.Should().Contain(r => r.Kind == PlannedReadKind.CModeCompound);
        plans[2].Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.CModeArea);
        line.SentFrames.Count(f => Header(f) == "QQ").Should().Be(1);
        values.Should().HaveCount(Scattered.Length);
        values.Select(v => v.Value.ToUInt16()).Should().BeEquivalentTo(Enumerable.Range(1, Scattered.Length).Select(i => (ushort)i));
    }

    [Fact]
    public async Task Of_two_watches_on_one_unit_the_one_QQ_saves_more_for_uses_its_registration()
    {
        // A PLC holds one QQ registration a unit: the watch QQ saves the most characters a second for uses it, the
        // other reads by area (rather than each taking the registration from the other every cycle) until it ends.
        var plc = Plc("CS1");
        await using var line = EmulatedLine.Start(plc, "CS1");
        PlcTag[] few = [.. Scattered.Take(4).Select(t => PlcTag.Parse(t))];
        PlcTag[] many = [.. Scattered.Skip(4).Select(t => PlcTag.Parse(t))];
        var options = new WatchOptions { Interval = TimeSpan.Zero, ReportEveryCycle = true, ReportPlans = true };
        await using IAsyncEnumerator<WatchEvent> small = line.Client.WatchAsync(few, options).GetAsyncEnumerator();
        IAsyncEnumerator<WatchEvent> large = line.Client.WatchAsync(many, options).GetAsyncEnumerator();

        ReadPlan smallPlan = (await NextPlan(small)).Plan!;
        ReadPlan largePlan = (await NextPlan(large)).Plan!;

        largePlan.Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.CModeCompound);
        smallPlan.Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.CModeArea).And.HaveCount(4);

        // The large watch ends: the small one takes the registration at its next cycle.
        await large.DisposeAsync();
        (await NextPlan(small)).Plan!.Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.CModeCompound);

        static async Task<WatchEvent> NextPlan(IAsyncEnumerator<WatchEvent> watch)
        {
            while (await watch.MoveNextAsync())
            {
                if (watch.Current.Kind == WatchEventKind.Planned)
                {
                    return watch.Current;
                }
            }

            throw new Xunit.Sdk.XunitException("The watch ended.");
        }
    }

    private static VirtualPlc Plc(string model)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        for (int i = 0; i < Scattered.Length; i++)
        {
            plc.WriteWord(PlcArea.Dm, i * 20, (ushort)(i + 1));
        }

        return plc;
    }

    private static async Task ReadTwiceAsync(EmulatedLine line)
    {
        for (int round = 0; round < 2; round++)
        {
            PlcTagValue[] values = await line.Client.ReadTagsAsync(Scattered);
            values.Select(v => (ushort)v.Value).Should().Equal(Enumerable.Range(1, Scattered.Length).Select(i => (ushort)i));
        }
    }

    private static string Header(string frame) => frame.Length >= 5 ? frame.Substring(3, 2) : "";
}
