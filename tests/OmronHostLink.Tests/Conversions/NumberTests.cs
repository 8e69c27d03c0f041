using FsCheck;
using FsCheck.Xunit;

namespace OmronHostLink.Tests.Conversions;

public class NumberTests
{
    [Theory]
    [InlineData(0x0000, 0)]
    [InlineData(0x7FFF, 32767)]
    [InlineData(0x8000, -32768)]
    [InlineData(0xFFFF, -1)]
    public void Int16_is_a_reinterpretation(int word, int value)
    {
        PlcWords.ToInt16((ushort)word).Should().Be((short)value);
        PlcWords.FromInt16((short)value).Should().Be((ushort)word);
    }

    [Theory]
    [InlineData(-2, 0xFFFE, 0xFFFF)]
    [InlineData(1, 0x0001, 0x0000)]
    [InlineData(65536, 0x0000, 0x0001)]
    [InlineData(0x12345678, 0x5678, 0x1234)]
    [InlineData(int.MinValue, 0x0000, 0x8000)]
    [InlineData(int.MaxValue, 0xFFFF, 0x7FFF)]
    public void Int32_low_word_first_known_values(int value, int first, int second)
    {
        var words = new ushort[2];
        PlcWords.WriteInt32(value, words);
        words.Should().Equal((ushort)first, (ushort)second);
        PlcWords.ReadInt32(words).Should().Be(value);

        PlcWords.WriteInt32(value, words, WordOrder.HighWordFirst);
        words.Should().Equal((ushort)second, (ushort)first);
        PlcWords.ReadInt32(words, WordOrder.HighWordFirst).Should().Be(value);
    }

    [Fact]
    public void UInt32_known_values()
    {
        PlcWords.ReadUInt32(new ushort[] { 0xFFFE, 0xFFFF }).Should().Be(0xFFFFFFFEu);
        PlcWords.ReadUInt32(new ushort[] { 0x1234, 0x5678 }, WordOrder.HighWordFirst).Should().Be(0x12345678u);
        var words = new ushort[3];
        PlcWords.WriteUInt32(0xDEADBEEF, words);
        words.Should().Equal(0xBEEF, 0xDEAD, 0x0000);
    }

    [Theory]
    [InlineData(1.0f, 0x0000, 0x3F80)]
    [InlineData(-2.5f, 0x0000, 0xC020)]
    [InlineData(0.0f, 0x0000, 0x0000)]
    [InlineData(3.14159274f, 0x0FDB, 0x4049)]
    [InlineData(float.PositiveInfinity, 0x0000, 0x7F80)]
    public void Single_low_word_first_known_values(float value, int first, int second)
    {
        var words = new ushort[2];
        PlcWords.WriteSingle(value, words);
        words.Should().Equal((ushort)first, (ushort)second);
        PlcWords.ReadSingle(words).Should().Be(value);

        PlcWords.WriteSingle(value, words, WordOrder.HighWordFirst);
        words.Should().Equal((ushort)second, (ushort)first);
        PlcWords.ReadSingle(words, WordOrder.HighWordFirst).Should().Be(value);
    }

    [Fact]
    public void Single_keeps_NaN_and_negative_zero()
    {
        float.IsNaN(PlcWords.ReadSingle(new ushort[] { 0x0000, 0x7FC0 })).Should().BeTrue();
        var words = new ushort[2];
        PlcWords.WriteSingle(-0.0f, words);
        words.Should().Equal(0x0000, 0x8000);
    }

    [Fact]
    public void Only_the_first_two_words_are_read_or_written()
    {
        PlcWords.ReadInt32(new ushort[] { 0xFFFE, 0xFFFF, 0x1234 }).Should().Be(-2);
        var words = new ushort[] { 9, 9, 9, 9 };
        PlcWords.WriteInt32(-2, words.AsSpan(1));
        words.Should().Equal(9, 0xFFFE, 0xFFFF, 9);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    public void Too_short_spans_are_rejected(int length)
    {
        var words = new ushort[length];
        FluentActions.Invoking(() => PlcWords.ReadInt32(words)).Should().Throw<ArgumentException>()
            .WithMessage($"2 words are needed but the span holds {length}.*").Which.ParamName.Should().Be("words");
        FluentActions.Invoking(() => PlcWords.ReadUInt32(words)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcWords.ReadSingle(words)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcWords.WriteInt32(1, words)).Should().Throw<ArgumentException>().Which.ParamName.Should().Be("dest");
        FluentActions.Invoking(() => PlcWords.WriteUInt32(1, words)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcWords.WriteSingle(1, words)).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Undefined_word_order_is_rejected()
    {
        FluentActions.Invoking(() => PlcWords.ReadInt32(new ushort[2], (WordOrder)5)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => PlcWords.WriteInt32(0, new ushort[2], (WordOrder)5)).Should().Throw<ArgumentOutOfRangeException>();
    }

    // DoNotSize: the whole 32-bit range (plain int/uint stay within ±size, so both words would rarely be exercised).
    [Property]
    public bool Int32_round_trips_in_both_orders(DoNotSize<int> anyValue, bool highFirst)
    {
        int value = anyValue.Item;
        var order = highFirst ? WordOrder.HighWordFirst : WordOrder.LowWordFirst;
        var words = new ushort[2];
        PlcWords.WriteInt32(value, words, order);
        return PlcWords.ReadInt32(words, order) == value
            && PlcWords.ReadUInt32(words, order) == unchecked((uint)value);
    }

    [Property]
    public bool Orders_are_word_swaps_of_each_other(DoNotSize<uint> anyValue)
    {
        uint value = anyValue.Item;
        var low = new ushort[2];
        var high = new ushort[2];
        PlcWords.WriteUInt32(value, low, WordOrder.LowWordFirst);
        PlcWords.WriteUInt32(value, high, WordOrder.HighWordFirst);
        return low[0] == high[1] && low[1] == high[0] && low[0] == (ushort)value;
    }

    [Fact]
    public void Single_round_trips_bit_for_bit_over_random_patterns()
    {
        var random = new Random(20240611);
        var words = new ushort[2];
        for (var i = 0; i < 10_000; i++)
        {
            var bits = random.Next(int.MinValue, int.MaxValue);
            var value = BitConverter.Int32BitsToSingle(bits);
            var order = (i & 1) == 0 ? WordOrder.LowWordFirst : WordOrder.HighWordFirst;
            PlcWords.WriteSingle(value, words, order);
            BitConverter.SingleToInt32Bits(PlcWords.ReadSingle(words, order)).Should().Be(bits);
            PlcWords.ReadInt32(words, order).Should().Be(bits, "a REAL is the same two words as its bit pattern");
        }
    }
}
