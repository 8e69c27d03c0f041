using OmronHostLink.Gateway.TagImport;

namespace OmronHostLink.Gateway.Tests.TagImport;

/// <summary>
/// A Kepware tag export of an Omron Host Link device (TagImport/Samples, written from Kepware's column list and the
/// driver's C200H address table) translated to gateway tags.
/// </summary>
public sealed class KepwareTagCsvTests
{
    internal static TagImportResult ImportSample(string file)
    {
        using var reader = new StreamReader(Path.Combine(AppContext.BaseDirectory, "TagImport", "Samples", file));
        return KepwareTagCsv.Import(reader);
    }

    public static TheoryData<string, string, PlcValueType, int, bool> Expected => new()
    {
        { "Setpoint", "D100", PlcValueType.Word, 1, true },
        { "Offset", "D101", PlcValueType.Int16, 1, true },
        { "Batch", "D102", PlcValueType.Bcd, 1, false },
        { "Total", "D104", PlcValueType.Bcd32, 1, false },
        { "Position", "D106", PlcValueType.Int32, 1, false },
        { "Counter", "D108", PlcValueType.UInt32, 1, false },
        { "Temperature", "D110", PlcValueType.Float, 1, false },
        { "Recipe", "D120", PlcValueType.Word, 4, true },
        { "Matrix", "D130", PlcValueType.Int16, 6, false },
        { "Product", "D200", PlcValueType.String, 20, true },
        { "Alarm", "D300.05", PlcValueType.Bit, 1, false },
        { "Holding", "H10", PlcValueType.Word, 1, true },
        { "HoldBit", "H10.03", PlcValueType.Bit, 1, true },
        { "Aux", "A5", PlcValueType.Word, 1, false },
        { "AuxBit", "A5.15", PlcValueType.Bit, 1, false },
        { "LinkWord", "LR10", PlcValueType.Word, 1, true },
        { "LinkBit", "LR10.01", PlcValueType.Bit, 1, true },
        { "Inputs", "CIO10", PlcValueType.Word, 1, false },
        { "Input2", "CIO10.02", PlcValueType.Bit, 1, false },
        { "TimerPV", "T5", PlcValueType.Bcd, 1, false },
        { "TimerDone", "T5", PlcValueType.Bit, 1, false },
        { "Plain", "D400", PlcValueType.Word, 1, false },
    };

    [Theory]
    [MemberData(nameof(Expected))]
    public void Every_documented_address_form_and_data_type_translates(string name, string address, PlcValueType type, int count, bool writable)
    {
        TagImportResult result = ImportSample("kepware-c200h.csv");
        result.Problems.Should().BeEmpty();

        ImportedTag tag = result.Tags.Single(t => t.Name == name);
        PlcAddress.Parse(tag.Address).Should().Be(PlcAddress.Parse(address));
        tag.Type.Should().Be(type);
        tag.Count.Should().Be(count);
        tag.Writable.Should().Be(writable);
    }

    [Fact]
    public void The_scan_rate_description_and_line_come_along()
    {
        TagImportResult result = ImportSample("kepware-c200h.csv");
        result.Tags.Should().HaveCount(22);
        ImportedTag temperature = result.Tags.Single(t => t.Name == "Temperature");
        temperature.Interval.Should().Be(TimeSpan.FromSeconds(1));
        temperature.Description.Should().Be("Tank temperature");
        temperature.Line.Should().Be(8);
        result.Tags.Single(t => t.Name == "Plain").Interval.Should().BeNull("an empty Scan Rate leaves the gateway's default");
    }

    [Fact]
    public void Every_row_that_cannot_be_translated_is_named_by_line_and_nothing_is_imported()
    {
        TagImportResult result = ImportSample("kepware-bad-rows.csv");

        result.Succeeded.Should().BeFalse();
        result.Tags.Should().BeEmpty("a file is never imported half");
        result.Problems.Select(p => p.Line).Should().Equal(3, 4, 5, 6, 7, 8, 9, 10);
        result.Problems.Select(p => p.ToString()).Should().SatisfyRespectively(
            p => p.Should().StartWith("line 3: tag 'Scaled'").And.Contain("Scaling 'Linear'"),
            p => p.Should().StartWith("line 4: tag 'Chars'").And.Contain("LoHi"),
            p => p.Should().StartWith("line 5: tag 'Bytes'").And.Contain("Data Type 'Byte'"),
            p => p.Should().StartWith("line 6: tag 'Far'").And.Contain("DM99999"),
            p => p.Should().StartWith("line 7: tag 'BitWord'").And.Contain("bit address holds a Boolean"),
            p => p.Should().StartWith("line 8: tag name 'Good' is already used on line 2"),
            p => p.Should().StartWith("line 9: tag 'Writer'").And.Contain("Write Only"),
            p => p.Should().StartWith("line 10: Tag Name 'Bad/Name' contains '/'"));
    }

    [Theory]
    [InlineData("\"Address\",\"Data Type\"\r\n\"DM0100\",\"Word\"\r\n", "line 1: the header has no 'Tag Name' column")]
    [InlineData("\"Tag Name\",\"Address\"\r\n\"A\",\"DM0100\r\n", "line 1: the file is not CSV: line 2: a quoted field is not closed")]
    [InlineData("\"Tag Name\",\"Address\"\r\n", "line 1: the file has no tag rows")]
    [InlineData("\"Tag Name\",\"Address\",\"Data Type\"\r\n\"S\",\"DM0100\",\"String\"\r\n", "line 2: tag 'S', Address 'DM0100' (String): a String tag names its length")]
    [InlineData("\"Tag Name\",\"Address\",\"Data Type\"\r\n\"W\",\"DM0100\",\"Word Array\"\r\n", "line 2: tag 'W', Address 'DM0100' (Word Array): an array data type needs the dimensions")]
    [InlineData("\"Tag Name\",\"Address\",\"Data Type\"\r\n\"B\",\"DM0100 [2]\",\"Boolean\"\r\n", "line 2: tag 'B', Address 'DM0100 [2]' (Boolean): a Boolean tag names a bit")]
    [InlineData("\"Tag Name\",\"Address\",\"Data Type\",\"Scan Rate\"\r\n\"R\",\"DM0100\",\"Word\",\"fast\"\r\n", "line 2: tag 'R': Scan Rate 'fast'")]
    public void Files_that_cannot_be_read_say_why_with_the_line(string csv, string problem)
    {
        TagImportResult result = KepwareTagCsv.Import(new StringReader(csv));
        result.Tags.Should().BeEmpty();
        result.Problems.Select(p => p.ToString()).Should().ContainSingle().Which.Should().StartWith(problem);
    }

    [Fact]
    public void A_quoted_field_may_hold_commas_quotes_and_line_breaks_and_lines_still_count()
    {
        string csv = "\"Tag Name\",\"Address\",\"Data Type\",\"Description\"\r\n"
            + "\"A\",\"DM0100\",\"Word\",\"two\r\nlines, a \"\"quote\"\"\"\r\n"
            + "\"B\",\"DM0101\",\"Word\",\"\"\r\n";
        TagImportResult result = KepwareTagCsv.Import(new StringReader(csv));
        result.Problems.Should().BeEmpty();
        result.Tags[0].Description.Should().Be("two\r\nlines, a \"quote\"");
        result.Tags[1].Line.Should().Be(4, "the first record spans lines 2 and 3");
    }
}
