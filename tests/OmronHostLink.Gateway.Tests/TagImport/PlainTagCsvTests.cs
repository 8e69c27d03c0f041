using OmronHostLink.Gateway.TagImport;

namespace OmronHostLink.Gateway.Tests.TagImport;

public sealed class PlainTagCsvTests
{
    [Fact]
    public void Rows_become_tags_in_the_gateways_own_spelling()
    {
        const string csv = "name,address,type,writable,count,interval\n"
            + "level,D100,int16,true,4,250\n"
            + "run,CIO0.03,bit,false,,\n"
            + "label,D200,string,yes,12,\n"
            + "done,T5,bit,no,,\n";

        TagImportResult result = PlainTagCsv.Import(new StringReader(csv));

        result.Problems.Should().BeEmpty();
        result.Tags.Should().BeEquivalentTo(new[]
        {
            new ImportedTag(2, "level", "D100", PlcValueType.Int16, 4, true, TimeSpan.FromMilliseconds(250)),
            new ImportedTag(3, "run", PlcAddress.Parse("CIO0.03").ToString(), PlcValueType.Bit, 1, false),
            new ImportedTag(4, "label", "D200", PlcValueType.String, 12, true),
            new ImportedTag(5, "done", "T5", PlcValueType.Bit, 1, false),
        });
    }

    [Fact]
    public void Bad_rows_are_named_by_line_and_nothing_is_imported()
    {
        const string csv = "name,address,type,writable\n"
            + "ok,D100,word,false\n"
            + "bad type,D101,decimal,false\n"
            + "bad address,Q7,word,false\n"
            + "bad writable,D102,word,maybe\n"
            + "word bit,D103.02,word,false\n"
            + ",D104,word,false\n";

        TagImportResult result = PlainTagCsv.Import(new StringReader(csv));

        result.Tags.Should().BeEmpty();
        result.Problems.Select(p => p.ToString()).Should().SatisfyRespectively(
            p => p.Should().StartWith("line 3: tag 'bad type': type 'decimal' is not one of"),
            p => p.Should().StartWith("line 4: tag 'bad address': 'Q7' is not a valid PLC address"),
            p => p.Should().StartWith("line 5: tag 'bad writable': writable 'maybe'"),
            p => p.Should().StartWith("line 6: tag 'word bit': address D103.02 names a bit"),
            p => p.Should().StartWith("line 7: name is empty"));
    }

    [Fact]
    public void A_header_without_a_required_column_is_refused()
        => PlainTagCsv.Import(new StringReader("name,address,type\nx,D1,word\n")).Problems.Should().ContainSingle()
            .Which.ToString().Should().Contain("'writable'");
}
