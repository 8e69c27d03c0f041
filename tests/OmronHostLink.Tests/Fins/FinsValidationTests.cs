using System.Text;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

/// <summary>Range checks when constructing, and the FINS end codes a simulator answers malformed parameters with.</summary>
public class FinsValidationTests
{
    private static readonly FinsMemoryAddress D0 = new(FinsMemoryArea.DmWord, 0);

    [Fact]
    public void Read_limit_is_269_words_from_the_538_byte_response_limit()
    {
        MemoryAreaReadCommand.MaxResponseDataBytes.Should().Be(1076 / 2);
        MemoryAreaReadCommand.MaxWords.Should().Be(269);
        new MemoryAreaReadCommand(D0, 269).Count.Should().Be(269);
        new MemoryAreaReadCommand(D0, 0).ResponseDataLength.Should().Be(0);
        new MemoryAreaReadCommand(new FinsMemoryAddress(0x30, 0, 15), 538).Count.Should().Be(538);
        var tooMany = () => new MemoryAreaReadCommand(D0, 270);
        tooMany.Should().Throw<ArgumentOutOfRangeException>();
        var negative = () => new MemoryAreaReadCommand(D0, -1);
        negative.Should().Throw<ArgumentOutOfRangeException>();
        var uninitialised = () => new MemoryAreaReadCommand(default, 1);
        uninitialised.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Write_limit_keeps_the_command_frame_within_1115_characters()
    {
        MemoryAreaWriteCommand max = MemoryAreaWriteCommand.Words(D0, new ushort[MemoryAreaWriteCommand.MaxWords]);
        FinsMessage.EncodeCommandFrame(0, FinsHeader.Network(1, 1, 0, 0, 0, 0), max).Length.Should().BeLessThanOrEqualTo(FinsMessage.MaxFrameLength);
        var tooMany = () => MemoryAreaWriteCommand.Words(D0, new ushort[MemoryAreaWriteCommand.MaxWords + 1]);
        tooMany.Should().Throw<ArgumentException>();
        var odd = () => new MemoryAreaWriteCommand(D0, new byte[3]);
        odd.Should().Throw<ArgumentException>();
        var badBit = () => new MemoryAreaWriteCommand(new FinsMemoryAddress(0x30, 0), new byte[] { 2 });
        badBit.Should().Throw<ArgumentException>();
        var bitsToWordArea = () => MemoryAreaWriteCommand.Bits(D0, new[] { true });
        bitsToWordArea.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Addresses_are_checked()
    {
        var bit16 = () => new FinsMemoryAddress(FinsMemoryArea.CioBit, 0, 16);
        bit16.Should().Throw<ArgumentOutOfRangeException>();
        var bitOnWordArea = () => new FinsMemoryAddress(FinsMemoryArea.DmWord, 0, 1);
        bitOnWordArea.Should().Throw<ArgumentOutOfRangeException>();
        var word = () => new FinsMemoryAddress(FinsMemoryArea.DmWord, 65536);
        word.Should().Throw<ArgumentOutOfRangeException>();
        var area = () => new FinsMemoryAddress(0x55, 0);
        area.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Headers_are_checked()
    {
        var wait = () => FinsHeader.Direct(responseWait: 16);
        wait.Should().Throw<ArgumentOutOfRangeException>();
        var sid = () => FinsHeader.Direct(sid: 256);
        sid.Should().Throw<ArgumentOutOfRangeException>();
        var dna = () => FinsHeader.Network(128, 0, 0, 0, 0, 0);
        dna.Should().Throw<ArgumentOutOfRangeException>();
        var gct = () => FinsHeader.Network(0, 0, 0, 0, 0, 0, gct: 8);
        gct.Should().Throw<ArgumentOutOfRangeException>();
        var unit = () => FinsMessage.EncodeCommandFrame(32, FinsHeader.Direct(), FinsCommands.ClockReadCommand);
        unit.Should().Throw<ArgumentOutOfRangeException>();
        var response = () => FinsMessage.EncodeCommandFrame(0, FinsHeader.Direct().ToResponseHeader(), FinsCommands.ClockReadCommand);
        response.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Other_commands_are_checked()
    {
        var runProgram = () => new RunCommand(FinsCpuMode.Program);
        runProgram.Should().Throw<ArgumentOutOfRangeException>();
        var modeWithoutProgram = () => new RunCommand(null, FinsCpuMode.Run);
        modeWithoutProgram.Should().Throw<ArgumentException>();
        var year = () => new ClockWriteCommand(new DateTime(2070, 1, 1));
        year.Should().Throw<ArgumentOutOfRangeException>();
        var dowWithoutSecond = () => new ClockWriteCommand(new DateTime(2024, 1, 1), includeSecond: false, DayOfWeek.Monday);
        dowWithoutSecond.Should().Throw<ArgumentException>();
        var records = () => new ErrorLogReadCommand(0, ErrorLogReadCommand.MaxRecords + 1);
        records.Should().Throw<ArgumentOutOfRangeException>();
        var forceWord = () => new FinsForcedBit(FinsForceAction.ForceSet, D0);
        forceWord.Should().Throw<ArgumentException>();
        var noItems = () => new MultipleMemoryAreaReadCommand(Array.Empty<FinsMemoryAddress>());
        noItems.Should().Throw<ArgumentException>();
        var fillBits = () => new MemoryAreaFillCommand(new FinsMemoryAddress(0x30, 0), 1, 0);
        fillBits.Should().Throw<ArgumentException>();
    }

    public static IEnumerable<object[]> BadParameters() => new[]
    {
        new object[] { (ushort)0x0101, "82000000", (ushort)0x1002 },
        new object[] { (ushort)0x0101, "82000000000100", (ushort)0x1001 },
        new object[] { (ushort)0x0101, "550000000001", (ushort)0x1101 },
        new object[] { (ushort)0x0101, "300000100001", (ushort)0x1103 },
        new object[] { (ushort)0x0101, "82000000010E", (ushort)0x110B },
        new object[] { (ushort)0x0102, "8200000000021234", (ushort)0x1003 },
        new object[] { (ushort)0x0102, "30000000000102", (ushort)0x110C },
        new object[] { (ushort)0x0103, "B0000000000100", (ushort)0x1002 },
        new object[] { (ushort)0x0103, "300000000001AAAA", (ushort)0x1101 },
        new object[] { (ushort)0x0104, "820000", (ushort)0x1002 },
        new object[] { (ushort)0x0104, "82000000B00001", (ushort)0x1002 },
        new object[] { (ushort)0x0105, "8200000082006400", (ushort)0x1002 },
        new object[] { (ushort)0x0401, "FF", (ushort)0x1002 },
        new object[] { (ushort)0x0401, "FFFF00", (ushort)0x110C },
        new object[] { (ushort)0x0401, "FFFF0200", (ushort)0x1001 },
        new object[] { (ushort)0x0402, "FF", (ushort)0x1002 },
        new object[] { (ushort)0x0501, "0000", (ushort)0x1001 },
        new object[] { (ushort)0x0601, "00", (ushort)0x1001 },
        new object[] { (ushort)0x0620, "", (ushort)0x1002 },
        new object[] { (ushort)0x0620, "02", (ushort)0x110C },
        new object[] { (ushort)0x0701, "00", (ushort)0x1001 },
        new object[] { (ushort)0x0702, "24051713", (ushort)0x1002 },
        new object[] { (ushort)0x0702, "2413171345", (ushort)0x110C },
        new object[] { (ushort)0x0702, "240230134500", (ushort)0x110C },
        new object[] { (ushort)0x0702, "24051713453007", (ushort)0x110C },
        new object[] { (ushort)0x2101, "FF", (ushort)0x1002 },
        new object[] { (ushort)0x2102, "00000000", (ushort)0x110C },
        new object[] { (ushort)0x2102, "00000036", (ushort)0x110B },
        new object[] { (ushort)0x2301, "0002000130000100", (ushort)0x1003 },
        new object[] { (ushort)0x2301, "00010002300001", (ushort)0x1002 },
        new object[] { (ushort)0x2301, "000100053000010000", (ushort)0x1002 },
        new object[] { (ushort)0x2301, "000100053000010", (ushort)0x1002 },
        new object[] { (ushort)0x0101, "820000100001", (ushort)0x1103 },
        new object[] { (ushort)0x2302, "00", (ushort)0x1001 },
    };

    [Theory]
    [MemberData(nameof(BadParameters))]
    public void Bad_parameters_carry_the_end_code_to_answer(ushort code, string parametersHex, ushort expected)
    {
        byte[] parameters = Hex(parametersHex);
        var act = () => FinsCommand.Parse(code, parameters);
        FinsFormatException e = act.Should().Throw<FinsFormatException>().Which;
        e.EndCode.Raw.Should().Be(expected, e.Message);
        e.Should().BeAssignableTo<HostLinkException>();
    }

    [Fact]
    public void Forced_set_reset_with_an_unknown_designation_or_a_word_area_is_refused()
    {
        var designation = () => FinsCommand.Parse(0x2301, Hex("0001000530000100"));
        designation.Should().Throw<FinsFormatException>().Which.EndCode.Raw.Should().Be(0x110C);
        var word = () => FinsCommand.Parse(0x2301, Hex("0001000182000100"));
        word.Should().Throw<FinsFormatException>().Which.EndCode.Raw.Should().Be(0x1101);
    }

    [Fact]
    public void Too_many_parameters_for_any_frame_is_1001()
    {
        var act = () => FinsCommand.Parse(0x2801, new byte[FinsCommand.MaxParameterLength + 1]);
        act.Should().Throw<FinsFormatException>().Which.EndCode.Raw.Should().Be(0x1001);
    }

    [Fact]
    public void Unknown_command_code_becomes_a_raw_command()
    {
        FinsCommand command = FinsCommand.Parse(0x0210, new byte[] { 1, 2, 3 });
        var raw = command.Should().BeOfType<RawFinsCommand>().Subject;
        raw.CommandCode.Should().Be(0x0210);
        raw.Parameters.ToArray().Should().Equal(1, 2, 3);
    }

    [Theory]
    [InlineData("")]
    [InlineData("G")]
    [InlineData("00000000001018200000000000")]
    [InlineData("000000000010182000000000Z")]
    [InlineData("0000000")]
    [InlineData("04000000001")]
    public void Malformed_command_text_is_refused(string text)
    {
        var act = () => FinsMessage.ParseCommand(Encoding.ASCII.GetBytes(text), 0);
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.Malformed);
    }

    [Theory]
    [InlineData("")]
    [InlineData("0")]
    [InlineData("ZZ40000000010100001234")]
    [InlineData("0040000000010100001")]
    [InlineData("004000000001010000123G")]
    [InlineData("00400000000101")]
    [InlineData("0000000000010100001234")]
    [InlineData("00C0000200000000010500")]
    public void Malformed_response_text_is_refused(string text)
    {
        var act = () => FinsResponse.Parse(Encoding.ASCII.GetBytes(text), 0, FinsHeader.Direct(), 0x0101);
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.Malformed);
    }

    private static byte[] Hex(string hex)
    {
        var bytes = new byte[hex.Length / 2];
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[i] = Convert.ToByte(hex.Substring(i * 2, 2), 16);
        }

        return bytes;
    }
}
