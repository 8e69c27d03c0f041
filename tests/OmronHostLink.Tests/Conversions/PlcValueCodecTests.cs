namespace OmronHostLink.Tests.Conversions;

/// <summary>The one value codec: layouts from the CS/CJ manuals (W342; IEEE 754 bit patterns), both word orders.</summary>
public sealed class PlcValueCodecTests
{
    public static TheoryData<PlcValueType, ushort[], WordOrder, object> Layouts() => new()
    {
        { PlcValueType.Word, [0x04D2], WordOrder.LowWordFirst, (ushort)0x04D2 },
        { PlcValueType.UInt16, [0xFFFE], WordOrder.LowWordFirst, (ushort)65534 },
        { PlcValueType.Int16, [0xFFFE], WordOrder.LowWordFirst, (short)-2 },
        { PlcValueType.Bcd, [0x1234], WordOrder.LowWordFirst, 1234 },
        { PlcValueType.Bcd32, [0x5678, 0x1234], WordOrder.LowWordFirst, 12345678 },
        { PlcValueType.Bcd32, [0x1234, 0x5678], WordOrder.HighWordFirst, 12345678 },
        { PlcValueType.Int32, [0xFFFE, 0xFFFF], WordOrder.LowWordFirst, -2 },
        { PlcValueType.Int32, [0xFFFF, 0xFFFE], WordOrder.HighWordFirst, -2 },
        { PlcValueType.UInt32, [0x0000, 0x0001], WordOrder.LowWordFirst, 65536u },
        { PlcValueType.UInt32, [0x0001, 0x0000], WordOrder.HighWordFirst, 65536u },
        { PlcValueType.Float, [0x0000, 0x3F80], WordOrder.LowWordFirst, 1.0f },
        { PlcValueType.Float, [0x41AC, 0x0000], WordOrder.HighWordFirst, 21.5f },
        { PlcValueType.Double, [0x0000, 0x0000, 0x0000, 0x3FF0], WordOrder.LowWordFirst, 1.0 },
        { PlcValueType.Double, [0xC004, 0x0000, 0x0000, 0x0000], WordOrder.HighWordFirst, -2.5 },
        { PlcValueType.Double, [0x2D18, 0x5444, 0x21FB, 0x4009], WordOrder.LowWordFirst, Math.PI },
        { PlcValueType.String, [0x4142, 0x4300, 0x4444], WordOrder.LowWordFirst, "ABC" },
    };

    [Theory]
    [MemberData(nameof(Layouts))]
    public void Decodes_each_layout_and_encodes_it_back(PlcValueType type, ushort[] words, WordOrder order, object expected)
    {
        PlcValue value = PlcValueCodec.Decode(type, words, order);

        value.Type.Should().Be(type);
        value.ToObject().Should().Be(expected);
        if (type != PlcValueType.String)
        {
            var back = new ushort[words.Length];
            PlcValueCodec.Encode(value, back, order).Should().Be(words.Length);
            back.Should().Equal(words);
        }
    }

    [Fact]
    public void Sizes_follow_the_layouts()
    {
        PlcValueCodec.WordCount(PlcValueType.Word, 3).Should().Be(3);
        PlcValueCodec.WordCount(PlcValueType.Int32, 3).Should().Be(6);
        PlcValueCodec.WordCount(PlcValueType.Double, 2).Should().Be(8);
        PlcValueCodec.WordCount(PlcValueType.Bcd32, 2).Should().Be(4);
        PlcValueCodec.WordCount(PlcValueType.String, 5).Should().Be(3);
        PlcValueCodec.WordCount(PlcValueType.Bit, 4, firstBit: 14).Should().Be(2);
        PlcValueCodec.WordCount(PlcValueType.Bit, 16, firstBit: 0).Should().Be(1);
    }

    [Fact]
    public void Bits_run_across_words_from_the_first_bit()
    {
        PlcValue[] bits = PlcValueCodec.DecodeValues(PlcValueType.Bit, new ushort[] { 0x4000, 0x0002 }, 4, firstBit: 14);

        bits.Select(b => b.ToBoolean()).Should().Equal(true, false, false, true);
    }

    [Fact]
    public void Series_of_32_bit_values_honour_the_word_order()
    {
        ushort[] words = [0x0000, 0x0001, 0x0000, 0x0002];

        PlcValueCodec.DecodeValues(PlcValueType.UInt32, words, 2, WordOrder.LowWordFirst).Select(v => v.ToUInt32()).Should().Equal(0x10000u, 0x20000u);
        PlcValueCodec.DecodeValues(PlcValueType.UInt32, words, 2, WordOrder.HighWordFirst).Select(v => v.ToUInt32()).Should().Equal(1u, 2u);
    }

    [Fact]
    public void Text_stops_at_the_count_or_the_first_nul_and_only_checks_what_it_reads()
    {
        ushort[] words = [0x4142, 0x43C9];

        PlcValueCodec.DecodeValues(PlcValueType.String, words, 3).Single().ToString().Should().Be("ABC");
        FluentActions.Invoking(() => PlcValueCodec.DecodeValues(PlcValueType.String, words, 4)).Should().Throw<FormatException>().WithMessage("*0xC9*not ASCII*");
        PlcValueCodec.Decode(PlcValueType.String, new ushort[] { 0x4100, 0x4242 }).ToString().Should().Be("A");
    }

    [Fact]
    public void Words_that_hold_no_value_of_the_type_are_refused_or_reported()
    {
        FluentActions.Invoking(() => PlcValueCodec.Decode(PlcValueType.Bcd, new ushort[] { 0x12A4 })).Should().Throw<FormatException>().WithMessage("0x12A4 is not BCD*");
        PlcValueCodec.TryDecode(PlcValueType.Bcd, new ushort[] { 0x12A4 }, WordOrder.LowWordFirst, 0, out _).Should().BeFalse();
        PlcValueCodec.TryDecode(PlcValueType.String, new ushort[] { 0x41FF }, WordOrder.LowWordFirst, 0, out _).Should().BeFalse();
        PlcValueCodec.TryDecode(PlcValueType.Bcd, new ushort[] { 0x0042 }, WordOrder.LowWordFirst, 0, out PlcValue bcd).Should().BeTrue();
        bcd.ToInt32().Should().Be(42);
        FluentActions.Invoking(() => PlcValueCodec.Decode(PlcValueType.Bcd32, new ushort[] { 0x0000, 0x1B00 })).Should().Throw<FormatException>().WithMessage("0x1B000000 is not BCD*");
        PlcValueCodec.TryDecode(PlcValueType.Bcd32, new ushort[] { 0x0000, 0x1B00 }, WordOrder.LowWordFirst, 0, out _).Should().BeFalse();
        FluentActions.Invoking(() => PlcValue.FromBcd32(100_000_000)).Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Too_few_words_are_an_argument_error_not_a_value()
    {
        FluentActions.Invoking(() => PlcValueCodec.Decode(PlcValueType.Double, new ushort[3])).Should().Throw<ArgumentException>().WithMessage("*needs 4 words*");
        FluentActions.Invoking(() => PlcValueCodec.DecodeValues(PlcValueType.Int32, new ushort[3], 2)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcValueCodec.Encode(PlcValue.FromDouble(1), new ushort[2])).Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Values_say_what_they_hold_and_refuse_other_types()
    {
        PlcValue.FromWord(0x04D2).ToString().Should().Be("0x04D2");
        PlcValue.FromBit(true).ToString().Should().Be("1");
        PlcValue.FromSingle(21.5f).ToString().Should().Be("21.5");
        PlcValue.FromInt32(-7).ToString().Should().Be("-7");
        FluentActions.Invoking(() => PlcValue.FromInt32(1).ToSingle()).Should().Throw<InvalidCastException>().WithMessage("*int32*");
        FluentActions.Invoking(() => PlcValue.FromBcd(10000)).Should().Throw<ArgumentOutOfRangeException>();
        FluentActions.Invoking(() => PlcValue.FromString("é")).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => PlcValueCodec.Encode(PlcValue.FromBit(true), new ushort[1])).Should().Throw<ArgumentException>().WithMessage("*bit address*");
    }

    [Fact]
    public void Equal_values_are_equal_by_type_and_bits_so_nan_does_not_look_like_a_change()
    {
        PlcValue.FromSingle(float.NaN).Should().Be(PlcValue.FromSingle(float.NaN));
        PlcValue.FromWord(5).Should().NotBe(PlcValue.FromUInt16(5));
        (PlcValue.FromString("AB") == PlcValue.FromString("AB")).Should().BeTrue();
        PlcValue.FromDouble(0.0).Should().NotBe(PlcValue.FromDouble(-0.0));
    }

    [Fact]
    public void Every_value_survives_encode_then_decode()
    {
        var random = new Random(12);
        for (int i = 0; i < 500; i++)
        {
            foreach (WordOrder order in new[] { WordOrder.LowWordFirst, WordOrder.HighWordFirst })
            {
                long bits = ((long)random.Next() << 33) ^ ((long)random.Next() << 2) ^ random.Next(4);
                PlcValue[] values =
                [
                    PlcValue.FromInt32((int)bits),
                    PlcValue.FromUInt32((uint)bits),
                    PlcValue.FromInt16((short)bits),
                    PlcValue.FromSingle(BitConverter.Int32BitsToSingle((int)bits)),
                    PlcValue.FromDouble(BitConverter.Int64BitsToDouble(bits)),
                    PlcValue.FromBcd((int)((uint)bits % 10000)),
                ];
                foreach (PlcValue value in values)
                {
                    var words = new ushort[4];
                    int n = PlcValueCodec.Encode(value, words, order);
                    PlcValueCodec.Decode(value.Type, words.AsSpan(0, n), order).Should().Be(value);
                }
            }
        }
    }
}
