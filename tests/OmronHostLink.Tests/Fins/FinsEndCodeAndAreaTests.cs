using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

public class FinsEndCodeAndAreaTests
{
    [Theory]
    [InlineData(0x0000, "Normal completion")]
    [InlineData(0x0001, "Service canceled")]
    [InlineData(0x0105, "Node address range error")]
    [InlineData(0x0205, "Response timeout")]
    [InlineData(0x0302, "CPU Unit error")]
    [InlineData(0x0401, "Undefined command")]
    [InlineData(0x0402, "Not supported by model/version")]
    [InlineData(0x0504, "Too many relays")]
    [InlineData(0x1001, "Command too long")]
    [InlineData(0x1002, "Command too short")]
    [InlineData(0x1003, "Elements/data don't match")]
    [InlineData(0x1004, "Command format error")]
    [InlineData(0x1101, "Area classification missing")]
    [InlineData(0x1103, "Address range error")]
    [InlineData(0x110B, "Response too long")]
    [InlineData(0x110C, "Parameter error")]
    [InlineData(0x2101, "Write not possible: read-only")]
    [InlineData(0x2602, "Command error: incorrect password")]
    [InlineData(0x2607, "Command error: no execution right")]
    [InlineData(0x3001, "Access right error: no access right")]
    [InlineData(0x4001, "Abort: service aborted")]
    public void End_code_meanings(int code, string meaning)
    {
        new FinsEndCode((ushort)code).Meaning.Should().Be(meaning);
        new FinsEndCode((ushort)(code | 0x80C0)).Meaning.Should().Be(meaning, "flags are masked before the lookup");
    }

    public static IEnumerable<object[]> TableCodes()
    {
        int[] codes =
        {
            0x0000, 0x0001, 0x0101, 0x0102, 0x0103, 0x0104, 0x0105, 0x0106, 0x0201, 0x0202, 0x0203, 0x0204, 0x0205,
            0x0301, 0x0302, 0x0303, 0x0304, 0x0401, 0x0402, 0x0501, 0x0502, 0x0503, 0x0504,
            0x1001, 0x1002, 0x1003, 0x1004, 0x1005, 0x1101, 0x1102, 0x1103, 0x1104, 0x1106, 0x1109, 0x110A, 0x110B, 0x110C,
            0x2002, 0x2003, 0x2004, 0x2005, 0x2006, 0x2007, 0x2101, 0x2102, 0x2103, 0x2105, 0x2106, 0x2107, 0x2108,
            0x2201, 0x2202, 0x2203, 0x2204, 0x2205, 0x2206, 0x2207, 0x2208, 0x2301, 0x2302, 0x2303, 0x2401,
            0x2502, 0x2510, 0x2601, 0x2602, 0x2607, 0x260B, 0x3001, 0x4001,
        };
        return codes.Select(c => new object[] { c });
    }

    [Theory]
    [MemberData(nameof(TableCodes))]
    public void Every_code_of_the_protocol_table_is_defined(int code)
        => FinsEndCodes.IsDefined((ushort)code).Should().BeTrue();

    [Fact]
    public void Unknown_codes_say_so()
        => new FinsEndCode(0x7F3F).Meaning.Should().StartWith("Unknown");

    [Theory]
    [InlineData(FinsAreaKind.Cio, 0xB0, 0x30)]
    [InlineData(FinsAreaKind.Work, 0xB1, 0x31)]
    [InlineData(FinsAreaKind.Holding, 0xB2, 0x32)]
    [InlineData(FinsAreaKind.Auxiliary, 0xB3, 0x33)]
    [InlineData(FinsAreaKind.Dm, 0x82, 0x02)]
    [InlineData(FinsAreaKind.EmCurrentBank, 0x98, 0x0A)]
    public void Area_codes_of_the_protocol_table(object kindValue, int word, int bit)
    {
        // The kind arrives as object: the test method is public, the protocol types are internal.
        var kind = (FinsAreaKind)kindValue;
        FinsMemoryArea.WordCode(kind).Should().Be((byte)word);
        FinsMemoryArea.BitCode(kind).Should().Be((byte)bit);
        FinsMemoryArea.ElementSize((byte)word).Should().Be(2);
        FinsMemoryArea.ElementSize((byte)bit).Should().Be(1);
        FinsMemoryArea.IsBitArea((byte)bit).Should().BeTrue();
        FinsMemoryArea.IsBitArea((byte)word).Should().BeFalse();
    }

    [Fact]
    public void Timer_counter_areas()
    {
        FinsMemoryArea.WordCode(FinsAreaKind.TimerCounterPv).Should().Be(0x89);
        FinsMemoryArea.BitCode(FinsAreaKind.TimerCounterFlag).Should().Be(0x09);
        var noBit = () => FinsMemoryArea.BitCode(FinsAreaKind.TimerCounterPv);
        noBit.Should().Throw<ArgumentException>();
        var noWord = () => FinsMemoryArea.WordCode(FinsAreaKind.TimerCounterFlag);
        noWord.Should().Throw<ArgumentException>();
        FinsMemoryArea.TimerAddress(10).Should().Be(10);
        FinsMemoryArea.CounterAddress(10).Should().Be(0x800A);
        FinsMemoryArea.CounterAddress(4095).Should().Be(0x8FFF);
        var range = () => FinsMemoryArea.TimerAddress(4096);
        range.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void EM_banks_0_to_C()
    {
        for (int bank = 0; bank <= 0xC; bank++)
        {
            FinsMemoryArea.WordCode(FinsAreaKind.Em, bank).Should().Be((byte)(0xA0 + bank));
            FinsMemoryArea.BitCode(FinsAreaKind.Em, bank).Should().Be((byte)(0x20 + bank));
        }

        var bankD = () => FinsMemoryArea.WordCode(FinsAreaKind.Em, 0xD);
        bankD.Should().Throw<ArgumentOutOfRangeException>();
        var bankOnDm = () => FinsMemoryArea.WordCode(FinsAreaKind.Dm, 1);
        bankOnDm.Should().Throw<ArgumentOutOfRangeException>();
    }
}
