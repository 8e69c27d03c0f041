namespace OmronHostLink.Tests.Conversions;

public class BitTests
{
    [Theory]
    [InlineData(0x0001, 0, true)]
    [InlineData(0x0001, 1, false)]
    [InlineData(0x8000, 15, true)]
    [InlineData(0x0020, 5, true)]
    [InlineData(0xFFDF, 5, false)]
    public void GetBit_reads_bit_n_from_the_least_significant_end(int word, int bit, bool expected) =>
        PlcWords.GetBit((ushort)word, bit).Should().Be(expected);

    [Fact]
    public void SetBit_sets_and_clears_one_bit()
    {
        PlcWords.SetBit(0x0000, 5, true).Should().Be(0x0020);
        PlcWords.SetBit(0xFFFF, 5, false).Should().Be(0xFFDF);
        PlcWords.SetBit(0x0000, 15, true).Should().Be(0x8000);
        PlcWords.SetBit(0x8000, 15, true).Should().Be(0x8000);
        PlcWords.SetBit(0x1234, 0, false).Should().Be(0x1234);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(16)]
    public void Bit_numbers_outside_0_to_15_are_rejected(int bit)
    {
        FluentActions.Invoking(() => PlcWords.GetBit(0, bit)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => PlcWords.SetBit(0, bit, true)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void ToBits_and_FromBits_are_inverse_for_every_word()
    {
        Span<bool> bits = stackalloc bool[16];
        for (var word = 0; word <= 0xFFFF; word++)
        {
            PlcWords.ToBits((ushort)word, bits);
            PlcWords.FromBits(bits).Should().Be((ushort)word);
        }
    }

    [Fact]
    public void ToBits_puts_bit_n_at_index_n()
    {
        var bits = PlcWords.ToBits(0x8001);
        bits.Should().HaveCount(16);
        bits[0].Should().BeTrue();
        bits[15].Should().BeTrue();
        bits.Count(b => b).Should().Be(2);
        PlcWords.FromBits(new[] { false, true }).Should().Be(0x0002);
        PlcWords.FromBits(ReadOnlySpan<bool>.Empty).Should().Be(0);
    }

    [Fact]
    public void Span_sizes_are_checked()
    {
        FluentActions.Invoking(() => PlcWords.ToBits(0, new bool[15])).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcWords.FromBits(new bool[17])).Should().Throw<ArgumentException>();
    }
}
