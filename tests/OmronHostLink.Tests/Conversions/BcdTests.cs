using FsCheck;
using FsCheck.Fluent;
using FsCheck.Xunit;

namespace OmronHostLink.Tests.Conversions;

public class BcdTests
{
    [Theory]
    [InlineData(0, 0x0000)]
    [InlineData(7, 0x0007)]
    [InlineData(10, 0x0010)]
    [InlineData(1234, 0x1234)]
    [InlineData(9999, 0x9999)]
    public void Word_BCD_known_values(int value, int word)
    {
        PlcWords.ToBcd(value).Should().Be((ushort)word);
        PlcWords.FromBcd((ushort)word).Should().Be(value);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(10000)]
    [InlineData(int.MaxValue)]
    public void ToBcd_rejects_values_outside_0_to_9999(int value) =>
        FluentActions.Invoking(() => PlcWords.ToBcd(value)).Should().Throw<ArgumentOutOfRangeException>()
            .WithMessage($"*0–9999; {value} does not fit*");

    [Theory]
    [InlineData(0x12A4, "0x12A4 is not BCD: digit A is not 0–9.")]
    [InlineData(0xF000, "0xF000 is not BCD: digit F is not 0–9.")]
    [InlineData(0x000B, "0x000B is not BCD: digit B is not 0–9.")]
    public void FromBcd_rejects_hex_digits_naming_the_word(int word, string message) =>
        FluentActions.Invoking(() => PlcWords.FromBcd((ushort)word)).Should().Throw<FormatException>().WithMessage(message);

    [Fact]
    public void Two_word_BCD_known_values()
    {
        PlcWords.ToBcd32(12345678).Should().Be(0x12345678u);
        PlcWords.ToBcd32(99999999).Should().Be(0x99999999u);
        PlcWords.FromBcd32(0x00010000).Should().Be(10000);

        Span<ushort> words = stackalloc ushort[2];
        PlcWords.WriteBcd32(12345678, words);
        words.ToArray().Should().Equal(0x5678, 0x1234);
        PlcWords.WriteBcd32(12345678, words, WordOrder.HighWordFirst);
        words.ToArray().Should().Equal(0x1234, 0x5678);

        PlcWords.ReadBcd32(new ushort[] { 0x5678, 0x1234 }).Should().Be(12345678);
        PlcWords.ReadBcd32(new ushort[] { 0x1234, 0x5678 }, WordOrder.HighWordFirst).Should().Be(12345678);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(100_000_000)]
    public void Two_word_BCD_rejects_out_of_range_values(int value)
    {
        FluentActions.Invoking(() => PlcWords.ToBcd32(value)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => PlcWords.WriteBcd32(value, new ushort[2])).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Two_word_BCD_rejects_hex_digits_and_short_spans()
    {
        FluentActions.Invoking(() => PlcWords.ReadBcd32(new ushort[] { 0x0000, 0x1C00 }))
            .Should().Throw<FormatException>().WithMessage("0x1C000000 is not BCD*");
        FluentActions.Invoking(() => PlcWords.ReadBcd32(new ushort[] { 0x1234 })).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcWords.WriteBcd32(1, new ushort[1])).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Every_word_BCD_value_round_trips()
    {
        for (var value = 0; value <= 9999; value++)
        {
            PlcWords.FromBcd(PlcWords.ToBcd(value)).Should().Be(value);
        }
    }

    [Fact]
    public void Exactly_the_valid_BCD_words_decode()
    {
        var valid = 0;
        for (var word = 0; word <= 0xFFFF; word++)
        {
            var isBcd = ((word >> 12) & 0xF) <= 9 && ((word >> 8) & 0xF) <= 9 && ((word >> 4) & 0xF) <= 9 && (word & 0xF) <= 9;
            try
            {
                var value = PlcWords.FromBcd((ushort)word);
                PlcWords.ToBcd(value).Should().Be((ushort)word);
                valid++;
            }
            catch (FormatException)
            {
                isBcd.Should().BeFalse($"0x{word:X4} is BCD");
            }
        }

        valid.Should().Be(10000);
    }

    [Property]
    public Property Two_word_BCD_round_trips_in_both_orders() =>
        Prop.ForAll(
            Gen.Choose(0, PlcWords.MaxBcd32).ToArbitrary(),
            Gen.Elements(WordOrder.LowWordFirst, WordOrder.HighWordFirst).ToArbitrary(),
            (value, order) =>
            {
                var words = new ushort[2];
                PlcWords.WriteBcd32(value, words, order);
                return PlcWords.ReadBcd32(words, order) == value
                    && PlcWords.FromBcd32(PlcWords.ToBcd32(value)) == value;
            });
}
