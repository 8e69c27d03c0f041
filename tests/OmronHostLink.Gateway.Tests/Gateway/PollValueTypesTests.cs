using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Polling;

namespace OmronHostLink.Gateway.Tests.Gateway;

public sealed class PollValueTypesTests
{
    private static string Format(string type, string address, int count, params ushort[] words)
    {
        PollValueTypes.TryParse(type, out PlcValueType t).Should().BeTrue();
        PlcAddress a = PlcAddress.Parse(address);
        PollValueTypes.WordCount(t, a, count).Should().Be(words.Length);
        return PollValueTypes.Format(t, a, count, words, WordOrder.LowWordFirst);
    }

    [Theory]
    [InlineData("word", "D0", 2, new ushort[] { 0x04D2, 0xFFFF }, "[0x04D2, 0xFFFF]")]
    [InlineData("bcd", "D0", 1, new ushort[] { 0x1234 }, "1234")]
    [InlineData("int16", "D0", 2, new ushort[] { 0xFFFE, 7 }, "[-2, 7]")]
    [InlineData("uint16", "D0", 1, new ushort[] { 0xFFFE }, "65534")]
    [InlineData("int32", "D0", 1, new ushort[] { 0xFFFF, 0xFFFF }, "-1")]
    [InlineData("uint32", "D0", 1, new ushort[] { 0x0000, 0x0001 }, "65536")]
    [InlineData("float", "D0", 1, new ushort[] { 0x0000, 0x41AC }, "21.5")]
    [InlineData("string", "D0", 3, new ushort[] { 0x4142, 0x4344 }, "\"ABC\"")]
    [InlineData("bit", "CIO10.14", 4, new ushort[] { 0x4000, 0x0002 }, "[1, 0, 0, 1]")]
    public void Values_are_formatted_as_the_type_says(string type, string address, int count, ushort[] words, string expected)
        => Format(type, address, count, words).Should().Be(expected);

    [Fact]
    public void A_word_that_is_not_bcd_is_refused()
        => FluentActions.Invoking(() => Format("bcd", "D0", 1, 0x00A1)).Should().Throw<FormatException>();

    [Theory]
    [InlineData("real")]
    [InlineData("3")]
    [InlineData("")]
    [InlineData(null)]
    public void Unknown_type_names_are_refused(string? name) => PollValueTypes.TryParse(name, out _).Should().BeFalse();
}
