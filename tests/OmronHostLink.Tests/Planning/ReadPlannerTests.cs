using OmronHostLink.Transports;
using OmronHostLink.Planning;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Planning;

public class ReadPlannerTests
{
    // Area-read planning; the compound read (QQ) on top of it is tested in CompoundPlanTests.
    private static readonly ReadPlanner CMode = new(HostLinkCommandSet.CMode) { UseCompoundRead = CompoundReadMode.Off };
    private static readonly ReadPlanner Fins = new(HostLinkCommandSet.Fins);

    private static PlcTag[] Tags(params string[] addresses) => addresses.Select(a => new PlcTag(a)).ToArray();

    [Fact]
    public void Character_costs_match_the_frames()
    {
        // RD of 30 words: 17-character command, 131-character answer.
        ReadPlanner.CModeReadCharacters(PlcArea.Dm, 30, out int exchanges).Should().Be(17 + 131);
        exchanges.Should().Be(1);

        // 31 words: a first frame of 30 (130 characters: no '*'), the host's CR, a last frame of 1 (8).
        ReadPlanner.CModeReadCharacters(PlcArea.Dm, 31, out exchanges).Should().Be(17 + 130 + 1 + 8);
        exchanges.Should().Be(2);

        // 1000 words: 1 + 32 frames.
        ReadPlanner.CModeReadCharacters(PlcArea.Dm, 1000, out exchanges);
        exchanges.Should().Be(33);

        // RE carries a bank: two characters more.
        ReadPlanner.CModeReadCharacters(PlcArea.Em, 1, out _).Should().Be(ReadPlanner.CModeReadCharacters(PlcArea.Dm, 1, out _) + 2);

        // FINS: 0101 = 34 + (27 + 4n); 0104 = (22 + 8k) + (27 + 6k).
        ReadPlanner.FinsReadCharacters(1).Should().Be(34 + 31);
        ReadPlanner.MultipleChars(3).Should().Be(22 + 24 + 27 + 18);
    }

    [Fact]
    public void Overlapping_and_duplicate_tags_are_read_once()
    {
        var tags = new[]
        {
            new PlcTag("D100"), new PlcTag("D100"), new PlcTag("D100", PlcValueType.Int32), new PlcTag("D101", PlcValueType.Float),
            new PlcTag("D100.03", PlcValueType.Bit),
        };
        ReadPlan plan = CMode.Plan(tags);
        plan.Reads.Should().ContainSingle();
        plan.Reads[0].Start.Should().Be(PlcAddress.Parse("D100"));
        plan.Reads[0].Count.Should().Be(3);
    }

    [Fact]
    public void Small_gaps_are_read_through_and_large_gaps_split()
    {
        // A new RD costs 17 + 11 = 28 characters; a word of gap costs 4: gaps up to 6 words are read through.
        CMode.Plan(Tags("D0", "D7")).Reads.Should().ContainSingle().Which.Count.Should().Be(8);
        CMode.Plan(Tags("D0", "D8")).Reads.Should().HaveCount(2);
    }

    [Fact]
    public void A_turnaround_makes_commands_dearer_so_larger_gaps_are_merged()
    {
        var slow = new ReadPlanner(HostLinkCommandSet.CMode, LineTiming.Default, TimeSpan.FromMilliseconds(20)) { UseCompoundRead = CompoundReadMode.Off };
        slow.Plan(Tags("D0", "D8")).Reads.Should().ContainSingle();
        slow.Plan(Tags("D0", "D30")).Reads.Should().HaveCount(2);
    }

    [Fact]
    public void Areas_banks_and_units_are_never_merged()
    {
        var tags = new[]
        {
            new PlcTag("D0"), new PlcTag("H0"), new PlcTag("CIO0"), new PlcTag("E1_0"), new PlcTag("E2_0"),
            new PlcTag("D1", unit: 3), new PlcTag("D2"),
        };
        ReadPlan plan = CMode.Plan(tags);
        plan.Reads.Select(r => (r.Unit, r.Start.ToString(), r.Count)).Should().BeEquivalentTo(new[]
        {
            (0, "CIO0", 1), (0, "H0", 1), (0, "D0", 3), (0, "E1_0", 1), (0, "E2_0", 1), (3, "D1", 1),
        });
    }

    [Fact]
    public void CMode_reads_long_ranges_as_one_transaction()
    {
        ReadPlan plan = CMode.Plan(Tags(Enumerable.Range(0, 1000).Select(i => $"D{i}").ToArray()));
        plan.Reads.Should().ContainSingle().Which.Count.Should().Be(1000);
        plan.Exchanges.Should().Be(33);
    }

    [Fact]
    public void Fins_cuts_area_reads_at_the_0101_limit()
    {
        ReadPlan plan = Fins.Plan(Tags(Enumerable.Range(0, 1000).Select(i => $"D{i}").ToArray()));
        plan.Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.FinsArea && r.Count <= MemoryAreaReadCommand.MaxWords);
        plan.Reads.Sum(r => r.Count).Should().Be(1000);
        plan.Reads.Should().HaveCount(4);
    }

    [Fact]
    public void Completion_flags_are_read_apart_from_present_values_in_runs_a_short_gap_read_through()
    {
        PlcTag[] tags = [PlcTag.Parse("T5:bit"), PlcTag.Parse("T6:bit"), PlcTag.Parse("T5"), PlcTag.Parse("T9:bit"), PlcTag.Parse("T1500:bit"), PlcTag.Parse("C7:bit")];
        tags[0].IsCompletionFlag.Should().BeTrue();
        tags[2].IsCompletionFlag.Should().BeFalse("T5 without a type is the present value");

        ReadPlan plan = CMode.Plan(tags);
        plan.Reads.Select(r => (r.Kind, r.Start.ToString(), r.Count)).Should().BeEquivalentTo(new[]
        {
            (PlannedReadKind.CModeArea, "T5", 1),
            (PlannedReadKind.CModeCompletionFlags, "T5", 5), // T5-T9: three flags read through cost less than another RG
            (PlannedReadKind.CModeCompletionFlags, "T1500", 1),
            (PlannedReadKind.CModeCompletionFlags, "C7", 1),
        });
        plan.Reads.Where(r => r.Kind == PlannedReadKind.CModeCompletionFlags).Should().OnlyContain(r => r.IsCompletionFlags);
        // RG of 5: 17-character command; answer of 7 + 5 flags + FCS, *, CR = 16 (as RD: 7 + 4n + 4).
        plan.Reads.Single(r => r.Count == 5).Characters.Should().Be(17 + 16);

        ReadPlan fins = new ReadPlanner(HostLinkCommandSet.Fins, useMultipleRead: false).Plan(tags);
        fins.Reads.Where(r => r.IsCompletionFlags).Should().OnlyContain(r => r.Kind == PlannedReadKind.FinsCompletionFlags);
        fins.Reads.Should().Contain(r => r.Kind == PlannedReadKind.FinsArea && r.Start.ToString() == "T5");
    }

    [Fact]
    public void A_bit_tag_on_a_word_that_is_not_a_timer_or_counter_is_refused()
    {
        FluentActions.Invoking(() => new PlcTag("D100", PlcValueType.Bit)).Should().Throw<ArgumentException>().WithMessage("*bit address such as D100.00, or a timer/counter number*");
        new PlcTag("C7", PlcValueType.Bit).IsCompletionFlag.Should().BeTrue();
    }

    [Fact]
    public void Fins_gathers_isolated_words_of_every_area_into_one_0104()
    {
        ReadPlan plan = Fins.Plan(Tags("D0", "D500", "H10", "W3", "CIO2000", "T5", "C7", "E3_100"));
        plan.Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.FinsMultiple);
        plan.Reads[0].Count.Should().Be(8);
    }

    [Fact]
    public void Fins_keeps_dense_runs_as_area_reads_and_scattered_words_as_items()
    {
        string[] dense = Enumerable.Range(100, 40).Select(i => $"D{i}").ToArray();
        ReadPlan plan = Fins.Plan(Tags([.. dense, "D5000", "H7", "A500"]));
        plan.Reads.Should().HaveCount(2);
        plan.Reads.Should().ContainSingle(r => r.Kind == PlannedReadKind.FinsArea && r.Count == 40);
        plan.Reads.Should().ContainSingle(r => r.Kind == PlannedReadKind.FinsMultiple && r.Count == 3);
    }

    [Fact]
    public void A_lone_item_batch_that_costs_more_than_an_area_read_becomes_an_area_read()
    {
        // Five contiguous words: 0104 = 49 + 70 characters, 0101 = 61 + 20.
        ReadPlan plan = Fins.Plan(Tags("D10", "D11", "D12", "D13", "D14"));
        plan.Reads.Should().ContainSingle().Which.Kind.Should().Be(PlannedReadKind.FinsArea);
    }

    [Fact]
    public void The_0104_limit_splits_items_into_several_commands()
    {
        string[] scattered = Enumerable.Range(0, 300).Select(i => $"D{i * 100}").ToArray();
        ReadPlan plan = Fins.Plan(Tags(scattered));
        plan.Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.FinsMultiple && r.Count <= MultipleMemoryAreaReadCommand.MaxItems);
        plan.Reads.Sum(r => r.Count).Should().Be(300);
        plan.Reads.Should().HaveCount(3);
    }

    [Fact]
    public void Without_multiple_read_fins_uses_area_reads()
    {
        var planner = new ReadPlanner(HostLinkCommandSet.Fins, useMultipleRead: false);
        planner.Plan(Tags("D0", "D500", "H10")).Reads.Should().OnlyContain(r => r.Kind == PlannedReadKind.FinsArea).And.HaveCount(3);
    }

    [Fact]
    public void CMode_refuses_what_it_cannot_reach_before_anything_is_sent()
    {
        FluentActions.Invoking(() => CMode.Plan(Tags("W0"))).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => CMode.Plan(Tags("D10000"))).Should().Throw<ArgumentException>();
        Fins.Plan(Tags("W0", "D10000")).Reads.Should().NotBeEmpty();
    }

    [Fact]
    public void Tags_check_their_type_against_the_address()
    {
        FluentActions.Invoking(() => new PlcTag("D0", PlcValueType.Bit)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new PlcTag("D0.01", PlcValueType.Word)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new PlcTag("D32767", PlcValueType.Int32)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => new PlcTag("D0", unit: 32)).Should().Throw<ArgumentOutOfRangeException>();
        new PlcTag("D0", PlcValueType.Float).WordCount.Should().Be(2);
    }

    [Fact]
    public void Resolve_decodes_every_type_from_the_read_words()
    {
        var tags = new[]
        {
            new PlcTag("D100", PlcValueType.Word), new PlcTag("D101", PlcValueType.Int16), new PlcTag("D102", PlcValueType.Int32),
            new PlcTag("D104", PlcValueType.Float), new PlcTag("D106", PlcValueType.Bcd), new PlcTag("D107.15", PlcValueType.Bit),
            new PlcTag("D102", PlcValueType.UInt32),
        };
        ReadPlan plan = CMode.Plan(tags);
        plan.Reads.Should().ContainSingle();
        var words = new ushort[8];
        words[0] = 0xBEEF;
        words[1] = 0xFFFE;
        PlcWords.WriteInt32(-123456, words.AsSpan(2));
        PlcWords.WriteSingle(1.5f, words.AsSpan(4));
        words[6] = 0x1234;
        words[7] = 0x8000;
        PlcTagValue[] values = plan.Resolve(new[] { words });
        values.Select(v => v.Value).Should().Equal((ushort)0xBEEF, (short)-2, -123456, 1.5f, 1234, true, unchecked((uint)-123456));
        values[2].Words.Should().Equal(words[2], words[3]);
    }

    [Fact]
    public void Resolve_rejects_results_that_do_not_match_the_reads()
    {
        ReadPlan plan = CMode.Plan(Tags("D0", "D100"));
        FluentActions.Invoking(() => plan.Resolve(new[] { new ushort[1] })).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => plan.Resolve(new[] { new ushort[1], new ushort[2] })).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Scattered_sets_cost_no_more_than_one_read_per_tag_and_cover_every_tag()
    {
        var random = new Random(7);
        for (int round = 0; round < 50; round++)
        {
            var tags = new List<PlcTag>();
            for (int i = 0; i < 60; i++)
            {
                PlcValueType type = (PlcValueType)random.Next(7);
                string area = new[] { "D", "H", "CIO", "A", "E1_" }[random.Next(5)];
                int max = area switch { "H" => 510, "A" => 958, "CIO" => 6142, _ => 9998 };
                int word = random.Next(0, max);
                string address = type == PlcValueType.Bit ? $"{area}{word}.{random.Next(16)}" : $"{area}{word}";
                tags.Add(new PlcTag(address, type, random.Next(3) == 0 ? 2 : null));
            }

            foreach (ReadPlanner planner in new[] { CMode, Fins })
            {
                ReadPlan plan = planner.Plan(tags);
                ReadPlan naive = new ReadPlanner(planner.CommandSet, useMultipleRead: false) { UseCompoundRead = CompoundReadMode.Off }.Plan(tags);
                plan.Characters.Should().BeLessThanOrEqualTo(tags.Sum(t => planner.CommandSet == HostLinkCommandSet.CMode
                    ? ReadPlanner.CModeReadCharacters(t.Address.Area, t.WordCount, out _)
                    : ReadPlanner.FinsReadCharacters(t.WordCount)));
                plan.TransactionCount.Should().BeLessThanOrEqualTo(naive.TransactionCount);

                // Every tag resolves from the words read (the dictionary lookup would throw otherwise).
                ushort[][] results = plan.Reads.Select(r => new ushort[r.Count]).ToArray();
                plan.Resolve(results).Should().HaveCount(tags.Count);
            }
        }
    }
}
