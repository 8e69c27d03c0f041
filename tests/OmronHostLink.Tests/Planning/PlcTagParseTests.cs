using OmronHostLink.Planning;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Planning;

/// <summary>Tag text (<c>address[:type]</c>) and ReadTagsAsync from text.</summary>
public sealed class PlcTagParseTests
{
    [Theory]
    [InlineData("D100", "D100", PlcValueType.Word)]
    [InlineData("D100:float", "D100", PlcValueType.Float)]
    [InlineData(" D100 : FLOAT ", "D100", PlcValueType.Float)]
    [InlineData("E1_200:int32", "E1_200", PlcValueType.Int32)]
    [InlineData("CIO10.03", "CIO10.03", PlcValueType.Bit)]
    [InlineData("H10.15:bit", "H10.15", PlcValueType.Bit)]
    [InlineData("D20:bcd32", "D20", PlcValueType.Bcd32)]
    [InlineData("D30:double", "D30", PlcValueType.Double)]
    public void Text_gives_the_address_and_the_type(string text, string address, PlcValueType type)
    {
        PlcTag tag = PlcTag.Parse(text);

        tag.Address.Should().Be(PlcAddress.Parse(address));
        tag.Type.Should().Be(type);
        tag.Unit.Should().BeNull();
    }

    [Theory]
    [InlineData("", "*has no address*")]
    [InlineData(":float", "*has no address*")]
    [InlineData("D100:real", "'D100:real' is not a tag: 'real' is not a tag type; use one of word, bcd, int16, uint16, int32, uint32, float, bit, double, bcd32*")]
    [InlineData("D100:string", "*'string' is not a tag type*")]
    [InlineData("D100:float[4]", "*takes no count*ReadAsync<T>(address, count)*")]
    [InlineData("D100:bit", "*a bit tag needs a bit address such as D100.00*")]
    [InlineData("D100.02:int16", "*D100.02 names a bit*word address such as D100*")]
    [InlineData("D32767:float", "*runs past the end of the area*")]
    [InlineData("Q7:word", "'Q7:word' is not a tag: 'Q7' is not a valid PLC address*")]
    public void Bad_text_is_refused_saying_why(string text, string message)
        => FluentActions.Invoking(() => PlcTag.Parse(text)).Should().Throw<FormatException>().WithMessage(message);

    [Fact]
    public void The_unit_is_passed_not_written()
    {
        PlcTag.Parse("D1:uint16", unit: 5).Unit.Should().Be(5);
        FluentActions.Invoking(() => PlcTag.Parse("D1", unit: 32)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public async Task ReadTagsAsync_reads_tag_text_in_one_planned_read()
    {
        await using InProcessLine line = InProcessLine.Start();
        line.Plc.WriteWord(PlcArea.Dm, 100, 0xFFFE);
        line.Plc.WriteWords(PlcArea.Dm, 102, new ushort[] { 0x0000, 0x4049 }); // 3.140625f, low word first
        line.Plc.WriteWord(PlcArea.Dm, 104, 0x0008);

        PlcTagValue[] values = await line.Client.ReadTagsAsync(new[] { "D100:int16", "D102:float", "D104.03", "D104" });

        values.Select(v => v.Value).Should().Equal((short)-2, 3.140625f, true, (ushort)8);
        line.FramesSent.Should().Be(1);
    }

    [Fact]
    public async Task Bad_tag_text_sends_nothing()
    {
        await using InProcessLine line = InProcessLine.Start();

        await FluentActions.Awaiting(async () => await line.Client.ReadTagsAsync(new[] { "D100", "D101:nope" })).Should().ThrowAsync<FormatException>();

        line.FramesSent.Should().Be(0);
    }
}
