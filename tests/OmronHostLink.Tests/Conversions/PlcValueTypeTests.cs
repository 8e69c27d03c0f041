using OmronHostLink.Planning;

namespace OmronHostLink.Tests.Conversions;

public sealed class PlcValueTypeTests
{
    [Fact]
    public void Every_type_parses_from_its_own_name_in_any_case_and_numbers_do_not()
    {
        foreach (PlcValueType type in Enum.GetValues<PlcValueType>())
        {
            PlcValueTypes.TryParse(type.Name().ToUpperInvariant(), out PlcValueType back).Should().BeTrue();
            back.Should().Be(type);
        }

        PlcValueTypes.TryParse("3", out _).Should().BeFalse();
        PlcValueTypes.TryParse(null, out _).Should().BeFalse();
        PlcValueTypes.Names.Should().Equal("word", "bcd", "int16", "uint16", "int32", "uint32", "float", "string", "bit", "double", "bcd32");
    }

    [Fact]
    public void Tags_take_fixed_size_types_only()
    {
        new PlcTag("D0", PlcValueType.UInt16).WordCount.Should().Be(1);
        new PlcTag("D0", PlcValueType.UInt32).WordCount.Should().Be(2);
        FluentActions.Invoking(() => new PlcTag("D0", PlcValueType.String)).Should().Throw<ArgumentException>().WithMessage("*ReadStringAsync*");
    }
}
