using FsCheck;
using FsCheck.Fluent;
using FsCheck.Xunit;

namespace OmronHostLink.Tests.Conversions;

public class TextTests
{
    [Fact]
    public void Two_characters_a_word_high_byte_first()
    {
        PlcWords.FromString("AB").Should().Equal(0x4142);
        PlcWords.FromString("HELLO").Should().Equal(0x4845, 0x4C4C, 0x4F00);
        PlcWords.FromString("").Should().BeEmpty();
        PlcWords.ReadString(new ushort[] { 0x4845, 0x4C4C, 0x4F00 }).Should().Be("HELLO");
        PlcWords.ReadString(new ushort[] { 0x4142 }).Should().Be("AB");
    }

    [Theory]
    [InlineData(0, 0)]
    [InlineData(1, 1)]
    [InlineData(2, 1)]
    [InlineData(5, 3)]
    [InlineData(int.MaxValue, 1073741824)]
    public void WordsForString_rounds_up(int length, int words) =>
        PlcWords.WordsForString(length).Should().Be(words);

    [Fact]
    public void WordsForString_rejects_negative_lengths() =>
        FluentActions.Invoking(() => PlcWords.WordsForString(-1)).Should().Throw<ArgumentOutOfRangeException>();

    [Fact]
    public void ReadString_stops_at_the_first_NUL_byte()
    {
        PlcWords.ReadString(new ushort[] { 0x4142, 0x0043, 0x4445 }).Should().Be("AB");
        PlcWords.ReadString(new ushort[] { 0x4100, 0xFFFF }).Should().Be("A", "bytes after the NUL are not text");
        PlcWords.ReadString(new ushort[] { 0x0041 }).Should().BeEmpty();
        PlcWords.ReadString(ReadOnlySpan<ushort>.Empty).Should().BeEmpty();
    }

    [Fact]
    public void ReadString_rejects_bytes_above_0x7F()
    {
        FluentActions.Invoking(() => PlcWords.ReadString(new ushort[] { 0x4142, 0x43C9 }))
            .Should().Throw<FormatException>().WithMessage("Word 1 (0x43C9) holds byte 0xC9, which is not ASCII*");
        FluentActions.Invoking(() => PlcWords.ReadString(new ushort[] { 0x8041 }))
            .Should().Throw<FormatException>().WithMessage("Word 0 (0x8041) holds byte 0x80*");
    }

    [Fact]
    public void WriteString_writes_only_the_words_it_needs()
    {
        var words = new ushort[] { 0xAAAA, 0xAAAA, 0xAAAA, 0xAAAA };
        PlcWords.WriteString("ABC", words).Should().Be(2);
        words.Should().Equal(0x4142, 0x4300, 0xAAAA, 0xAAAA);
        PlcWords.WriteString("", words).Should().Be(0);
    }

    [Fact]
    public void WriteString_rejects_a_short_span_without_writing()
    {
        var words = new ushort[] { 0xAAAA, 0xAAAA };
        FluentActions.Invoking(() => PlcWords.WriteString("HELLO", words)).Should().Throw<ArgumentException>()
            .WithMessage("5 characters need 3 words but the span holds 2.*").Which.ParamName.Should().Be("dest");
        words.Should().Equal(0xAAAA, 0xAAAA);
    }

    [Theory]
    [InlineData("héllo", "'é' (U+00E9) at position 1 is not ASCII*")]
    [InlineData("AB€", "'€' (U+20AC) at position 2 is not ASCII*")]
    [InlineData("\u0080", "*U+0080) at position 0*")]
    public void Non_ASCII_text_is_rejected_naming_the_character(string text, string message)
    {
        var words = new ushort[] { 0xAAAA, 0xAAAA };
        FluentActions.Invoking(() => PlcWords.FromString(text)).Should().Throw<ArgumentException>().WithMessage(message)
            .Which.ParamName.Should().Be("text");
        FluentActions.Invoking(() => PlcWords.WriteString(text, words)).Should().Throw<ArgumentException>().WithMessage(message);
        words.Should().Equal(0xAAAA, 0xAAAA);
    }

    [Fact]
    public void Null_text_is_rejected()
    {
        FluentActions.Invoking(() => PlcWords.FromString(null!)).Should().Throw<ArgumentNullException>();
        FluentActions.Invoking(() => PlcWords.WriteString(null!, new ushort[1])).Should().Throw<ArgumentNullException>();
    }

    [Fact]
    public void Long_strings_round_trip()
    {
        var text = new string('x', 1001);
        PlcWords.ReadString(PlcWords.FromString(text)).Should().Be(text);
    }

    [Property]
    public Property ASCII_text_without_NUL_round_trips() =>
        Prop.ForAll(
            Gen.Choose(1, 0x7F).Select(c => (char)c).ArrayOf().Select(chars => new string(chars)).ToArbitrary(),
            text =>
            {
                var words = PlcWords.FromString(text);
                return words.Length == PlcWords.WordsForString(text.Length) && PlcWords.ReadString(words) == text;
            });
}
