using OmronHostLink.Protocol;

namespace OmronHostLink.Tests.Protocol;

public sealed class EndCodeTests
{
    // PROTOCOL.md §4 and the category table of the protocol issue.
    [Theory]
    [InlineData("00", EndCodeCategory.None)]
    [InlineData("01", EndCodeCategory.ModeNotAllowed)]
    [InlineData("02", EndCodeCategory.ModeNotAllowed)]
    [InlineData("0B", EndCodeCategory.ModeNotAllowed)]
    [InlineData("03", EndCodeCategory.Protected)]
    [InlineData("23", EndCodeCategory.Protected)]
    [InlineData("04", EndCodeCategory.AddressOrEntry)]
    [InlineData("15", EndCodeCategory.AddressOrEntry)]
    [InlineData("13", EndCodeCategory.FrameDamaged)]
    [InlineData("A3", EndCodeCategory.FrameDamaged)]
    [InlineData("14", EndCodeCategory.Format)]
    [InlineData("A4", EndCodeCategory.Format)]
    [InlineData("18", EndCodeCategory.Length)]
    [InlineData("A8", EndCodeCategory.Length)]
    [InlineData("16", EndCodeCategory.NotSupported)]
    [InlineData("IC", EndCodeCategory.NotSupported)]
    [InlineData("21", EndCodeCategory.CpuError)]
    [InlineData("19", EndCodeCategory.NotExecutable)]
    [InlineData("20", EndCodeCategory.NotExecutable)]
    [InlineData("A5", EndCodeCategory.AddressOrEntry)]
    public void Every_end_code_maps_to_its_category(string code, EndCodeCategory category)
    {
        EndCodes.TryParse(System.Text.Encoding.ASCII.GetBytes(code), out EndCode endCode).Should().BeTrue();
        endCode.ToCode().Should().Be(code);
        endCode.Category().Should().Be(category);
        EndCodes.IsDefined(endCode).Should().BeTrue();

        var e = new HostLinkEndCodeException(endCode, "RD", 7);
        e.Category.Should().Be(category);
        e.Message.Should().Contain(code).And.Contain("07").And.Contain("RD").And.Contain(endCode.Meaning());
    }

    [Theory]
    [InlineData("00", "Normal completion")]
    [InlineData("01", "RUN mode")]
    [InlineData("02", "MONITOR mode")]
    [InlineData("13", "FCS")]
    [InlineData("14", "Format")]
    [InlineData("15", "Entry number")]
    [InlineData("18", "Frame length")]
    [InlineData("21", "CPU")]
    [InlineData("A3", "FCS error in the second")]
    [InlineData("A8", "frame length error in the second")]
    public void Meanings_follow_the_manual(string code, string fragment)
    {
        EndCodes.TryParse(System.Text.Encoding.ASCII.GetBytes(code), out EndCode endCode);
        endCode.Meaning().Should().Contain(fragment);
    }

    [Fact]
    public void Every_defined_code_has_a_meaning_and_round_trips()
    {
        foreach (EndCode code in EndCodes.All)
        {
            code.Meaning().Should().NotStartWith("Unknown");
            EndCodes.TryParse(System.Text.Encoding.ASCII.GetBytes(code.ToCode()), out EndCode back).Should().BeTrue();
            back.Should().Be(code);
        }

        EndCodes.All.Should().HaveCount(29);
    }

    [Fact]
    public void An_unknown_code_is_kept_and_named()
    {
        var code = (EndCode)0x7E;
        code.Meaning().Should().Be("Unknown end code 7E");
        code.Category().Should().Be(EndCodeCategory.NotExecutable);
        EndCodes.IsDefined(code).Should().BeFalse();
    }

    [Fact]
    public void The_end_code_0D_written_by_one_public_suite_is_not_the_FCS_error()
    {
        // roof_sc_resp_0D_misencoded: end codes are hex digits copied from the table; FCS error is 13, not 0D.
        EndCodes.TryParse("0D"u8, out EndCode code).Should().BeTrue();
        code.Should().NotBe(EndCode.FcsError);
        EndCodes.IsDefined(code).Should().BeFalse();
    }
}
