namespace OmronHostLink.Tests.Models;

/// <summary>The profiles' ranges and messages, checked against the numbers the manuals print (docs/models.md).</summary>
public sealed class PlcModelProfileTests
{
    [Theory]
    // model, address, count, expected: null when the read is allowed, else a part of the message
    [InlineData("CP1E-E", "D0", 1, null)]
    [InlineData("CP1E-E", "D2047", 1, null)]
    [InlineData("CP1E-E", "D2048", 1, "D2048 is beyond the DM area of a CP1E E-type (D0–D2047).")]
    [InlineData("CP1E-E", "D2040", 10, "10 words from D2040 reach D2048, beyond the DM area of a CP1E E-type (D0–D2047).")]
    [InlineData("CP1E-N", "D8191", 1, null)]
    [InlineData("CP1E-N", "D8192", 1, "beyond the DM area of a CP1E N/NA-type (D0–D8191)")]
    [InlineData("CPM1A", "D1023", 1, null)]
    [InlineData("CPM1A", "D1024", 1, "D1024 is beyond the DM area of a CPM1/CPM1A (D0–D1023, D6144–D6655).")]
    [InlineData("CPM1A", "D6143", 1, "beyond the DM area")]
    [InlineData("CPM1A", "D6144", 512, null)]
    [InlineData("CPM1A", "D6656", 1, "beyond the DM area")]
    [InlineData("CPM1A", "CIO19", 1, null)]
    [InlineData("CPM1A", "CIO20", 1, "CIO20 is beyond the CIO area of a CPM1/CPM1A (CIO0–CIO19, CIO200–CIO255).")]
    [InlineData("CPM1A", "CIO255", 1, null)]
    [InlineData("CPM1A", "CIO256", 1, "beyond the CIO area")]
    [InlineData("CPM1A", "LR15", 1, null)]
    [InlineData("CPM1A", "LR16", 1, "LR16 is beyond the LR area of a CPM1/CPM1A (LR0–LR15).")]
    [InlineData("CPM1A", "H19", 1, null)]
    [InlineData("CPM1A", "H20", 1, "beyond the holding area (H)")]
    [InlineData("CPM1A", "A15", 1, null)]
    [InlineData("CPM1A", "A16", 1, "beyond the auxiliary area (A)")]
    [InlineData("CPM1A", "T127", 1, null)]
    [InlineData("CPM1A", "C128", 1, "beyond the counter area")]
    [InlineData("CPM1A", "W0", 1, "a CPM1/CPM1A has no work area (W)")]
    [InlineData("CPM1A", "E0_0", 1, "a CPM1/CPM1A has no EM area")]
    [InlineData("SRM1", "D2047", 1, null)]
    [InlineData("SRM1", "D2048", 1, "D2048 is beyond the DM area of an SRM1 (D0–D2047, D6144–D6655).")]
    [InlineData("C200HS", "D6655", 1, null)]
    [InlineData("C200HS", "D6656", 1, "D6656 is beyond the DM area of a C200HS (D0–D6655).")]
    [InlineData("C200HS", "CIO511", 1, null)]
    [InlineData("C200HS", "CIO512", 1, "beyond the CIO area")]
    [InlineData("C200HS", "LR63", 1, null)]
    [InlineData("C200HS", "LR64", 1, "beyond the LR area")]
    [InlineData("C200HS", "T511", 1, null)]
    [InlineData("C200HS", "T512", 1, "beyond the timer area")]
    [InlineData("C200HX", "E0_0", 1, "no EM area")]
    [InlineData("CQM1H-CPU61", "E0_6143", 1, null)]
    [InlineData("CQM1H-CPU61", "E0_6144", 1, "beyond the EM area")]
    [InlineData("CQM1H-CPU61", "E1_0", 1, "beyond the EM area")]
    [InlineData("CS1", "D32767", 1, null)]
    [InlineData("CS1", "W511", 1, null)]
    [InlineData("CS1", "LR199", 1, null)]
    [InlineData("CS1", "EC_32767", 1, null)]
    [InlineData("CP1L-L", "D9999", 1, null)]
    [InlineData("CP1L-L", "D10000", 1, "beyond the DM area of a CP1L L-type (D0–D9999, D32000–D32767)")]
    [InlineData("CP1H", "E0_0", 1, "no EM area")]
    public void Reads_are_checked_against_the_model(string model, string address, int count, string? expected)
    {
        var profile = PlcModelProfile.Parse(model);
        var start = PlcAddress.Parse(address);
        var read = () => profile.EnsureRange(start, count, forWrite: false);

        if (expected is null)
        {
            read.Should().NotThrow();
        }
        else
        {
            read.Should().Throw<ArgumentException>().Which.Message.Should().Contain(expected);
        }
    }

    [Theory]
    [InlineData("CPM1A", "CIO252", null)]
    [InlineData("CPM1A", "CIO253", "CIO253 is read-only on a CPM1/CPM1A (CIO253–CIO255 cannot be written by a host).")]
    [InlineData("C200HS", "CIO253", "read-only on a C200HS")]
    [InlineData("C200HS", "CIO256", null)]
    [InlineData("CS1", "A447", "read-only on a CS1/CJ1/CJ2")]
    [InlineData("CS1", "A448", null)]
    public void Writes_are_checked_against_the_models_read_only_ranges(string model, string address, string? expected)
    {
        var write = () => PlcModelProfile.Parse(model).EnsureRange(PlcAddress.Parse(address), 1, forWrite: true);

        if (expected is null)
        {
            write.Should().NotThrow();
        }
        else
        {
            write.Should().Throw<ArgumentException>().Which.Message.Should().Contain(expected);
        }
    }

    [Fact]
    public void A_write_that_runs_into_a_read_only_range_names_the_first_read_only_word()
    {
        var write = () => PlcModelProfile.Parse("CPM1A").EnsureRange(PlcAddress.Parse("CIO250"), 4, forWrite: true);

        write.Should().Throw<ArgumentException>().WithMessage("CIO253 is read-only*");
    }

    [Theory]
    [InlineData("cpm1a", "CPM1A")]
    [InlineData("CPM1", "CPM1A")]
    [InlineData("CPM2C", "CPM2A")]
    [InlineData("cp1e e", "CP1E-E")]
    [InlineData("CP1E E-type", "CP1E-E")]
    [InlineData("C200HG", "C200HX")]
    [InlineData("C200HX/HG/HE", "C200HX")]
    [InlineData("CJ2", "CS1")]
    [InlineData("CS/CJ", "CS1")]
    public void Models_are_found_by_their_names(string name, string profile)
    {
        PlcModelProfile.Parse(name).Name.Should().Be(profile);
    }

    [Fact]
    public void An_unknown_model_name_lists_the_known_ones()
    {
        FluentActions.Invoking(() => PlcModelProfile.Parse("C1000X")).Should().Throw<ArgumentException>()
            .WithMessage("'C1000X' is not a known PLC model; known models: C200H, C200HS, C200HX, CQM1, *CP1E-E*CS1.*");
    }

    [Fact]
    public void MM_code_30_is_the_CS_CJ_profile()
    {
        PlcModelProfile.FromModelCode(0x30).Should().BeSameAs(PlcModelProfile.Parse("CJ1"));
    }

    [Fact]
    public void MM_code_11_covers_several_models_and_assumes_only_what_all_of_them_have()
    {
        // W353 p300: 11 = C2000H/CQM1/CPM2A/CPM2C/CPM1/CPM1A/SRM1(-V2).
        var profile = PlcModelProfile.FromModelCode(0x11)!;

        profile.DisplayName.Should().Contain("CQM1").And.Contain("CPM1/CPM1A").And.Contain("SRM1").And.Contain("CPM2A/CPM2C");
        profile.Extent(PlcArea.Dm).Should().Be("D0–D1023, D6144–D6655");
        profile.Extent(PlcArea.Cio).Should().Be("CIO0–CIO19, CIO200–CIO255");
        profile.Extent(PlcArea.Link).Should().Be("LR0–LR15");
        profile.Extent(PlcArea.Timer).Should().Be("T0–T127");
        profile.Has(PlcArea.Em).Should().BeFalse();
        profile.SupportsFins.Should().BeFalse();
        profile.SupportsCompoundRead.Should().BeTrue("every model of code 11 lists QQ (CQM1/CPM1 manual p388, CQM1H p470, W353 p302)");
        FluentActions.Invoking(() => profile.EnsureRange(PlcAddress.Parse("D2000"), 1, false)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void MM_code_12_assumes_what_the_C200H_C200HS_and_C200HX_all_have()
    {
        var profile = PlcModelProfile.FromModelCode(0x12)!;

        profile.Extent(PlcArea.Dm).Should().Be("D0–D1999");
        profile.EnsureRange(PlcAddress.Parse("D1999"), 1, false);
        FluentActions.Invoking(() => profile.EnsureRange(PlcAddress.Parse("D6656"), 1, false)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void An_unknown_MM_code_has_no_profile()
    {
        PlcModelProfile.FromModelCode(0x77).Should().BeNull();
    }

    [Fact]
    public void Every_profile_cites_a_source_for_every_range_and_knows_its_commands()
    {
        foreach (var profile in PlcModelProfile.All)
        {
            profile.Areas.Should().NotBeEmpty(profile.Name);
            profile.Areas.Concat(profile.ZeroReadRanges).Should().OnlyContain(r => r.Source.Length > 0, profile.Name);
            profile.AcceptsCMode("RD").Should().BeTrue(profile.Name);
            profile.Describe().Should().Contain(profile.DisplayName);
        }
    }

    [Fact]
    public void The_older_families_have_no_FINS_and_share_timer_counter_numbers()
    {
        foreach (var name in new[] { "C200H", "C200HS", "C200HX", "CQM1", "CQM1H", "CPM1A", "CPM2A", "SRM1" })
        {
            var profile = PlcModelProfile.Parse(name);
            profile.SupportsFins.Should().BeFalse(name);
            profile.SharesTimerCounterNumbers.Should().BeTrue(name);
            profile.TimerCounterCoding.Should().Be(TimerCounterCoding.Bcd, name);
            FluentActions.Invoking(profile.EnsureFins).Should().Throw<NotSupportedException>().WithMessage("*does not take FINS*; use C-mode: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.CMode*plc.Unit(0, HostLinkCommandSet.CMode)*");
        }
    }

    [Fact]
    public void QQ_is_accepted_only_where_a_manual_lists_it()
    {
        PlcModelProfile.Parse("CPM1A").SupportsCompoundRead.Should().BeTrue();
        PlcModelProfile.Parse("CQM1H").SupportsCompoundRead.Should().BeTrue();
        PlcModelProfile.Parse("CS1").SupportsCompoundRead.Should().BeTrue();
        PlcModelProfile.Parse("CP2E").SupportsCompoundRead.Should().BeFalse();
        FluentActions.Invoking(() => PlcModelProfile.Parse("CP2E").EnsureCMode("QQ", "compound read")).Should().Throw<NotSupportedException>()
            .WithMessage("A CP2E does not accept the C-mode compound read (QQ).");
    }
}
