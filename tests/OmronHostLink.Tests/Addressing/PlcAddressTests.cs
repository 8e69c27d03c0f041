namespace OmronHostLink.Tests.Addressing;

public class PlcAddressTests
{
    [Theory]
    [InlineData(PlcArea.Cio, 6144)]
    [InlineData(PlcArea.Work, 512)]
    [InlineData(PlcArea.Holding, 512)]
    [InlineData(PlcArea.Auxiliary, 960)]
    [InlineData(PlcArea.Dm, 32768)]
    [InlineData(PlcArea.Timer, 4096)]
    [InlineData(PlcArea.Counter, 4096)]
    [InlineData(PlcArea.Em, 32768)]
    public void Area_sizes_are_those_of_CS_CJ(PlcArea area, int size) =>
        PlcAddress.AreaSize(area).Should().Be(size);

    [Fact]
    public void AreaSize_of_an_undefined_area_throws() =>
        FluentActions.Invoking(() => PlcAddress.AreaSize((PlcArea)99)).Should().Throw<ArgumentOutOfRangeException>();

    [Fact]
    public void Default_is_CIO0_as_a_word()
    {
        var address = default(PlcAddress);
        address.Area.Should().Be(PlcArea.Cio);
        address.Word.Should().Be(0);
        address.IsBit.Should().BeFalse();
        address.Bit.Should().Be(-1);
        address.ToString().Should().Be("CIO0");
    }

    [Fact]
    public void WordOf_and_BitOf_make_validated_addresses()
    {
        PlcAddress.WordOf(PlcArea.Dm, 100).Should().Be(PlcAddress.Parse("D100"));
        PlcAddress.WordOf(PlcArea.Em, 100, 1).Should().Be(PlcAddress.Parse("E1_100"));
        PlcAddress.BitOf(PlcArea.Cio, 100, 5).Should().Be(PlcAddress.Parse("CIO100.05"));
        PlcAddress.BitOf(PlcArea.Em, 100, 2, 12).ToString().Should().Be("EC_100.02");
    }

    [Theory]
    [InlineData(PlcArea.Dm, -1, 0)]
    [InlineData(PlcArea.Dm, 32768, 0)]
    [InlineData(PlcArea.Cio, 6144, 0)]
    [InlineData(PlcArea.Work, 512, 0)]
    [InlineData(PlcArea.Timer, 4096, 0)]
    [InlineData(PlcArea.Em, 0, 13)]
    [InlineData(PlcArea.Em, 0, -1)]
    [InlineData(PlcArea.Dm, 0, 1)]
    [InlineData((PlcArea)42, 0, 0)]
    public void WordOf_rejects_out_of_range_parts(PlcArea area, int word, int bank) =>
        FluentActions.Invoking(() => PlcAddress.WordOf(area, word, bank)).Should().Throw<ArgumentOutOfRangeException>();

    [Fact]
    public void WordOf_message_names_the_area_extent() =>
        FluentActions.Invoking(() => PlcAddress.WordOf(PlcArea.Dm, 32768))
            .Should().Throw<ArgumentOutOfRangeException>().WithMessage("*DM area (D0–D32767)*");

    [Theory]
    [InlineData(-1)]
    [InlineData(16)]
    public void BitOf_rejects_bits_outside_0_to_15(int bit) =>
        FluentActions.Invoking(() => PlcAddress.BitOf(PlcArea.Dm, 0, bit)).Should().Throw<ArgumentOutOfRangeException>();

    [Theory]
    [InlineData(PlcArea.Timer)]
    [InlineData(PlcArea.Counter)]
    public void Timers_and_counters_have_no_bits(PlcArea area)
    {
        FluentActions.Invoking(() => PlcAddress.BitOf(area, 5, 1))
            .Should().Throw<ArgumentException>().WithMessage("*cannot take a bit*");
        FluentActions.Invoking(() => PlcAddress.WordOf(area, 5).WithBit(1))
            .Should().Throw<ArgumentException>().WithMessage("*cannot take a bit*");
    }

    [Fact]
    public void WithBit_and_AsWord_switch_between_word_and_bit()
    {
        var word = PlcAddress.Parse("E1_100");
        var bit = word.WithBit(3);

        bit.ToString().Should().Be("E1_100.03");
        bit.AsWord().Should().Be(word);
        word.AsWord().Should().Be(word);
        bit.WithBit(15).ToString().Should().Be("E1_100.15");
        FluentActions.Invoking(() => word.WithBit(16)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Theory]
    [InlineData("D100", 5, "D105")]
    [InlineData("D100", -100, "D0")]
    [InlineData("D100.05", 2, "D102.05")]
    [InlineData("E1_100", 32667, "E1_32767")]
    [InlineData("T5", 1, "T6")]
    [InlineData("CIO0", 0, "CIO0")]
    public void Offset_moves_within_the_area(string start, int words, string expected) =>
        PlcAddress.Parse(start).Offset(words).ToString().Should().Be(expected);

    [Theory]
    [InlineData("D100", -101)]
    [InlineData("D32767", 1)]
    [InlineData("E1_32767", 1)]
    [InlineData("W511", 1)]
    [InlineData("D0", int.MinValue)]
    [InlineData("D32767", int.MaxValue)]
    public void Offset_outside_the_area_throws(string start, int words) =>
        FluentActions.Invoking(() => PlcAddress.Parse(start).Offset(words))
            .Should().Throw<ArgumentOutOfRangeException>().WithMessage($"*{start} offset by {words} words*");

    [Fact]
    public void Equality_compares_area_bank_word_and_bit()
    {
        var a = PlcAddress.Parse("D100");
        a.Should().Be(PlcAddress.Parse("DM 100"));
        (a == PlcAddress.Parse("d100")).Should().BeTrue();
        (a != PlcAddress.Parse("D100.00")).Should().BeTrue();
        a.Should().NotBe(PlcAddress.Parse("H100"));
        PlcAddress.Parse("E1_100").Should().NotBe(PlcAddress.Parse("E2_100"));
        a.Equals((object)PlcAddress.Parse("D100")).Should().BeTrue();
        a.Equals("D100").Should().BeFalse();
        a.GetHashCode().Should().Be(PlcAddress.Parse("D100").GetHashCode());
        new HashSet<PlcAddress> { a, PlcAddress.Parse("D100"), PlcAddress.Parse("D100.00"), PlcAddress.Parse("E0_100") }
            .Should().HaveCount(3);
    }
}
