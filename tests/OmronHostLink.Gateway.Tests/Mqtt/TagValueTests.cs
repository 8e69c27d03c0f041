using System.Text.Json;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Tests.Mqtt;

public sealed class TagValueTests
{
    private static readonly PlcAddress D100 = PlcAddress.Parse("D100");

    public static TheoryData<string, int, string, ushort[]> Decoded => new()
    {
        // type, count, expected JSON, words (values from the Omron conventions: low word first, ASCII high byte first)
        { "word", 1, "4660", [0x1234] },
        { "uint16", 2, "[0,65535]", [0x0000, 0xFFFF] },
        { "int16", 2, "[120,-340]", [120, 0xFEAC] },
        { "bcd", 1, "1234", [0x1234] },
        { "int32", 1, "-2", [0xFFFE, 0xFFFF] },
        { "uint32", 1, "65536", [0x0000, 0x0001] },
        { "float", 1, "21.5", [0x0000, 0x41AC] },
        { "string", 6, "\"MIX-A7\"", [0x4D49, 0x582D, 0x4137] },
        { "string", 4, "\"MIX-\"", [0x4D49, 0x582D, 0x4137] },
    };

    [Theory]
    [MemberData(nameof(Decoded))]
    public void Words_decode_to_typed_json_values(string type, int count, string json, ushort[] words)
    {
        PlcValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        object value = TagValues.Decode(t, D100, count, words, WordOrder.LowWordFirst);
        JsonSerializer.Serialize(value, value.GetType()).Should().Be(json);
    }

    [Fact]
    public void Bits_decode_from_their_bit_number_and_completion_flags_from_one_word()
    {
        object bits = TagValues.Decode(PlcValueType.Bit, PlcAddress.Parse("CIO10.14"), 4, [0b0100_0000_0000_0000, 0x0002], WordOrder.LowWordFirst);
        bits.Should().BeEquivalentTo(new[] { true, false, false, true });
        TagValues.Decode(PlcValueType.Bit, PlcAddress.Parse("T5"), 1, [1], WordOrder.LowWordFirst).Should().Be(true);
    }

    [Fact]
    public void Bcd_that_is_not_bcd_is_an_error_not_a_value()
    {
        Action act = () => TagValues.Decode(PlcValueType.Bcd, D100, 1, [0x12A4], WordOrder.LowWordFirst);
        act.Should().Throw<FormatException>();
    }

    public static TheoryData<string, int, string, ushort[]> Encoded => new()
    {
        { "word", 1, "65535", [0xFFFF] },
        { "int16", 1, "-340", [0xFEAC] },
        { "int16", 2, "[1,-1]", [0x0001, 0xFFFF] },
        { "bcd", 1, "9999", [0x9999] },
        { "int32", 1, "-2", [0xFFFE, 0xFFFF] },
        { "uint32", 1, "4294967295", [0xFFFF, 0xFFFF] },
        { "float", 1, "21.5", [0x0000, 0x41AC] },
        { "string", 5, "\"AB\"", [0x4142, 0x0000, 0x0000] },
        { "bit", 1, "true", [1] },
        { "bit", 1, "0", [0] },
    };

    [Theory]
    [MemberData(nameof(Encoded))]
    public void Json_values_encode_to_the_words_to_write(string type, int count, string json, ushort[] words)
    {
        PlcValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        using JsonDocument d = JsonDocument.Parse(json);
        WriteValueParser.TryEncode(t, count, d.RootElement, WordOrder.LowWordFirst, out ushort[] result, out string error).Should().BeTrue(error);
        result.Should().Equal(words);
    }

    public static TheoryData<string, int, string, string> Refused => new()
    {
        { "int16", 1, "40000", "int16 takes a whole number from -32768 to 32767; got 40000." },
        { "int16", 1, "1.5", "int16 takes a whole number from -32768 to 32767; got 1.5." },
        { "word", 1, "-1", "word takes a whole number from 0 to 65535; got -1." },
        { "uint16", 1, "\"12\"", "uint16 takes a whole number from 0 to 65535; got \"12\"." },
        { "bcd", 1, "10000", "bcd takes a whole number from 0 to 9999; got 10000." },
        { "uint32", 1, "-1", "uint32 takes a whole number from 0 to 4294967295; got -1." },
        { "float", 1, "1e39", "a float takes a JSON number" },
        { "float", 1, "null", "a float takes a JSON number" },
        { "bit", 1, "2", "a bit takes true or false (or 1 or 0); got 2." },
        { "int16", 2, "[1]", "the tag has 2 values: send a JSON array of 2; got [1]." },
        { "int16", 2, "5", "the tag has 2 values: send a JSON array of 2; got 5." },
        { "int16", 2, "[1,70000]", "item 1: int16 takes a whole number" },
        { "string", 3, "\"ABCD\"", "the text has 4 characters; the tag holds at most 3." },
        { "string", 3, "\"Ä\"", "a PLC string takes ASCII characters" },
        { "string", 3, "12", "a string tag takes a JSON string" },
    };

    [Theory]
    [MemberData(nameof(Refused))]
    public void Values_the_type_cannot_hold_are_refused_with_a_reason(string type, int count, string json, string reason)
    {
        PlcValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        using JsonDocument d = JsonDocument.Parse(json);
        WriteValueParser.TryEncode(t, count, d.RootElement, WordOrder.LowWordFirst, out _, out string error).Should().BeFalse();
        error.Should().Contain(reason);
    }

    [Theory]
    [InlineData("int32", "123456789")]
    [InlineData("float", "-0.125")]
    [InlineData("uint32", "3000000000")]
    public void High_word_first_round_trips(string type, string json)
    {
        PlcValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        using JsonDocument d = JsonDocument.Parse(json);
        WriteValueParser.TryEncode(t, 1, d.RootElement, WordOrder.HighWordFirst, out ushort[] words, out _).Should().BeTrue();
        object value = TagValues.Decode(t, D100, 1, words, WordOrder.HighWordFirst);
        JsonSerializer.Serialize(value, value.GetType()).Should().Be(json);
    }
}
