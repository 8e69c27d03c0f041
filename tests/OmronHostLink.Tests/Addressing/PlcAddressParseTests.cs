namespace OmronHostLink.Tests.Addressing;

public class PlcAddressParseTests
{
    [Theory]
    // DM
    [InlineData("D100", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("DM100", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("D 100", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("dm100", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("  d100\t", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("D0", PlcArea.Dm, 0, -1, 0, "D0")]
    [InlineData("D00100", PlcArea.Dm, 100, -1, 0, "D100")]
    [InlineData("D32767", PlcArea.Dm, 32767, -1, 0, "D32767")]
    [InlineData("D100.05", PlcArea.Dm, 100, 5, 0, "D100.05")]
    [InlineData("D100.15", PlcArea.Dm, 100, 15, 0, "D100.15")]
    // CIO
    [InlineData("CIO100", PlcArea.Cio, 100, -1, 0, "CIO100")]
    [InlineData("CIO 100", PlcArea.Cio, 100, -1, 0, "CIO100")]
    [InlineData("cio100", PlcArea.Cio, 100, -1, 0, "CIO100")]
    [InlineData("100", PlcArea.Cio, 100, -1, 0, "CIO100")]
    [InlineData("0", PlcArea.Cio, 0, -1, 0, "CIO0")]
    [InlineData("6143", PlcArea.Cio, 6143, -1, 0, "CIO6143")]
    [InlineData("CIO100.05", PlcArea.Cio, 100, 5, 0, "CIO100.05")]
    [InlineData("100.05", PlcArea.Cio, 100, 5, 0, "CIO100.05")]
    [InlineData("CIO 100.5", PlcArea.Cio, 100, 5, 0, "CIO100.05")]
    [InlineData("100.00", PlcArea.Cio, 100, 0, 0, "CIO100.00")]
    // Work
    [InlineData("W30", PlcArea.Work, 30, -1, 0, "W30")]
    [InlineData("WR30", PlcArea.Work, 30, -1, 0, "W30")]
    [InlineData("W30.06", PlcArea.Work, 30, 6, 0, "W30.06")]
    [InlineData("w511", PlcArea.Work, 511, -1, 0, "W511")]
    // Holding
    [InlineData("H10", PlcArea.Holding, 10, -1, 0, "H10")]
    [InlineData("HR10", PlcArea.Holding, 10, -1, 0, "H10")]
    [InlineData("H10.03", PlcArea.Holding, 10, 3, 0, "H10.03")]
    [InlineData("HR 511", PlcArea.Holding, 511, -1, 0, "H511")]
    // Auxiliary
    [InlineData("A448", PlcArea.Auxiliary, 448, -1, 0, "A448")]
    [InlineData("AR448", PlcArea.Auxiliary, 448, -1, 0, "A448")]
    [InlineData("A448.01", PlcArea.Auxiliary, 448, 1, 0, "A448.01")]
    [InlineData("A959", PlcArea.Auxiliary, 959, -1, 0, "A959")]
    // Timer / counter
    [InlineData("T5", PlcArea.Timer, 5, -1, 0, "T5")]
    [InlineData("TIM5", PlcArea.Timer, 5, -1, 0, "T5")]
    [InlineData("tim 4095", PlcArea.Timer, 4095, -1, 0, "T4095")]
    [InlineData("C7", PlcArea.Counter, 7, -1, 0, "C7")]
    [InlineData("CNT7", PlcArea.Counter, 7, -1, 0, "C7")]
    [InlineData("C4095", PlcArea.Counter, 4095, -1, 0, "C4095")]
    // EM
    [InlineData("E1_100", PlcArea.Em, 100, -1, 1, "E1_100")]
    [InlineData("EM1_100", PlcArea.Em, 100, -1, 1, "E1_100")]
    [InlineData("E1_100.03", PlcArea.Em, 100, 3, 1, "E1_100.03")]
    [InlineData("E0_0", PlcArea.Em, 0, -1, 0, "E0_0")]
    [InlineData("EC_100", PlcArea.Em, 100, -1, 12, "EC_100")]
    [InlineData("ec_32767", PlcArea.Em, 32767, -1, 12, "EC_32767")]
    [InlineData("EA_5.2", PlcArea.Em, 5, 2, 10, "EA_5.02")]
    [InlineData("E 1_100", PlcArea.Em, 100, -1, 1, "E1_100")]
    public void Parses_every_accepted_form(string text, PlcArea area, int word, int bit, int bank, string canonical)
    {
        var address = PlcAddress.Parse(text);

        address.Area.Should().Be(area);
        address.Word.Should().Be(word);
        address.Bit.Should().Be(bit);
        address.IsBit.Should().Be(bit >= 0);
        address.Bank.Should().Be(bank);
        address.ToString().Should().Be(canonical);
        PlcAddress.Parse(canonical).Should().Be(address, "the canonical form reads back to the same address");
        PlcAddress.TryParse(text, out var tried).Should().BeTrue();
        tried.Should().Be(address);
    }

    [Theory]
    [InlineData("", "empty")]
    [InlineData("   ", "empty")]
    [InlineData("D", "word number after 'D' is missing")]
    [InlineData("D-1", "found '-1'")]
    [InlineData("D32768", "D0–D32767")]
    [InlineData("CIO6144", "CIO0–CIO6143")]
    [InlineData("6144", "CIO0–CIO6143")]
    [InlineData("W512", "W0–W511")]
    [InlineData("H512", "H0–H511")]
    [InlineData("A960", "A0–A959")]
    [InlineData("T4096", "T0–T4095")]
    [InlineData("C4096", "C0–C4095")]
    [InlineData("T5.01", "cannot take a bit")]
    [InlineData("C7.00", "cannot take a bit")]
    [InlineData("E D_0", "bank D does not exist")]
    [InlineData("ED_0", "bank D does not exist")]
    [InlineData("EF_0", "bank F does not exist")]
    [InlineData("EX_0", "'X' is not a hex digit")]
    [InlineData("E10_0", "'10' is not a hex digit")]
    [InlineData("E_100", "bank is missing before '_'")]
    [InlineData("EM_100", "bank is missing before '_'")]
    [InlineData("E100", "needs a bank")]
    [InlineData("E1_", "missing")]
    [InlineData("E1_32768", "E1_0–E1_32767")]
    [InlineData("X100", "unknown area 'X'")]
    [InlineData("DX100", "found 'X100'")]
    [InlineData("D100.16", "bit '16'")]
    [InlineData("D100.005", "bit '005'")]
    [InlineData("D100.", "bit number after '.' is missing")]
    [InlineData("D100.x", "bit number after '.' is missing")]
    [InlineData("D1 00", "unexpected ' 00'")]
    [InlineData("D100 .05", "unexpected ' .05'")]
    [InlineData("D100.05.1", "unexpected '.1'")]
    [InlineData("D99999999999999", "outside the DM area")]
    [InlineData(".5", "unknown area")]
    [InlineData("D１００", "found '１００'")]
    public void Rejects_invalid_text_with_a_message_naming_it(string text, string reason)
    {
        var act = () => PlcAddress.Parse(text);

        act.Should().Throw<FormatException>()
            .Which.Message.Should().Contain($"'{text}'").And.Contain(reason);
        PlcAddress.TryParse(text, out var address).Should().BeFalse();
        address.Should().Be(default(PlcAddress));
    }

    [Fact]
    public void Parse_of_null_throws_ArgumentNullException() =>
        FluentActions.Invoking(() => PlcAddress.Parse(null!)).Should().Throw<ArgumentNullException>();

    [Fact]
    public void TryParse_of_null_is_false() =>
        PlcAddress.TryParse(null, out _).Should().BeFalse();

    [Fact]
    public void Every_word_of_every_area_round_trips_through_ToString()
    {
        foreach (var area in Enum.GetValues<PlcArea>())
        {
            var banks = area == PlcArea.Em ? 13 : 1;
            for (var bank = 0; bank < banks; bank++)
            {
                for (var word = 0; word < PlcAddress.AreaSize(area); word += 97)
                {
                    var address = PlcAddress.WordOf(area, word, bank);
                    PlcAddress.Parse(address.ToString()).Should().Be(address);
                    if (area is not (PlcArea.Timer or PlcArea.Counter))
                    {
                        var bit = address.WithBit(word % 16);
                        PlcAddress.Parse(bit.ToString()).Should().Be(bit);
                    }
                }
            }
        }
    }
}
