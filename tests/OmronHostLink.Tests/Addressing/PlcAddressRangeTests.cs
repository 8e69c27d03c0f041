namespace OmronHostLink.Tests.Addressing;

public class PlcAddressRangeTests
{
    private static Action Ensure(string address, int count, HostLinkCommandSet protocol, bool forWrite = false) =>
        () => PlcAddress.Parse(address).EnsureRange(count, protocol, forWrite);

    [Theory]
    [InlineData("D0", 32768, HostLinkCommandSet.Fins, true)]
    [InlineData("D32767", 1, HostLinkCommandSet.Fins, true)]
    [InlineData("D10000", 1, HostLinkCommandSet.Fins, false)]
    [InlineData("W0", 512, HostLinkCommandSet.Fins, true)]
    [InlineData("T4095", 1, HostLinkCommandSet.Fins, false)]
    [InlineData("EC_32767", 1, HostLinkCommandSet.Fins, true)]
    [InlineData("A0", 960, HostLinkCommandSet.Fins, false)]
    [InlineData("A448", 512, HostLinkCommandSet.Fins, true)]
    [InlineData("A0", 960, HostLinkCommandSet.CMode, false)]
    [InlineData("A448", 512, HostLinkCommandSet.CMode, true)]
    [InlineData("D0", 10000, HostLinkCommandSet.CMode, true)]
    [InlineData("D9999", 1, HostLinkCommandSet.CMode, false)]
    [InlineData("E1_9999", 1, HostLinkCommandSet.CMode, true)]
    [InlineData("CIO0", 6144, HostLinkCommandSet.CMode, true)]
    [InlineData("H0", 512, HostLinkCommandSet.CMode, true)]
    [InlineData("T2047", 1, HostLinkCommandSet.CMode, false)]
    [InlineData("C0", 2048, HostLinkCommandSet.CMode, true)]
    [InlineData("CIO100.05", 1, HostLinkCommandSet.CMode, false)]
    [InlineData("D9999.15", 1, HostLinkCommandSet.CMode, true)]
    public void Accepts_transfers_within_reach(string address, int count, HostLinkCommandSet protocol, bool forWrite) =>
        Ensure(address, count, protocol, forWrite).Should().NotThrow();

    [Theory]
    [InlineData(0)]
    [InlineData(-1)]
    [InlineData(int.MinValue)]
    public void Count_must_be_at_least_one(int count) =>
        Ensure("D100", count, HostLinkCommandSet.Fins).Should().Throw<ArgumentOutOfRangeException>()
            .WithMessage($"*D100 needs at least 1 word; count was {count}*").Which.ParamName.Should().Be("count");

    [Theory]
    [InlineData("D32760", 10, "10 words from D32760 run past the end of the DM area (D0–D32767)*")]
    [InlineData("CIO6000", 200, "200 words from CIO6000 run past the end of the CIO area (CIO0–CIO6143)*")]
    [InlineData("W500", 13, "13 words from W500 run past the end of the work area (W) (W0–W511)*")]
    [InlineData("E2_32767", 2, "2 words from E2_32767 run past the end of the EM area (E2_0–E2_32767)*")]
    [InlineData("T4000", 100, "100 words from T4000 run past the end of the timer area (T0–T4095)*")]
    [InlineData("D0", int.MaxValue, "*run past the end of the DM area*")]
    public void Words_must_fit_in_the_area(string address, int count, string message)
    {
        Ensure(address, count, HostLinkCommandSet.Fins).Should().Throw<ArgumentOutOfRangeException>().WithMessage(message);
        Ensure(address, count, HostLinkCommandSet.CMode).Should().Throw<ArgumentOutOfRangeException>().WithMessage(message);
    }

    [Theory]
    [InlineData(HostLinkCommandSet.CMode)]
    [InlineData(HostLinkCommandSet.Fins)]
    public void Writes_to_read_only_auxiliary_words_are_refused(HostLinkCommandSet protocol)
    {
        Ensure("A0", 1, protocol, forWrite: true).Should().Throw<ArgumentException>()
            .WithMessage("A0 is in the read-only part of the auxiliary area (A0–A447); writes can go to A448–A959 only.");
        Ensure("A447", 1, protocol, forWrite: true).Should().Throw<ArgumentException>().WithMessage("A447 is in the read-only*");
        Ensure("A440", 20, protocol, forWrite: true).Should().Throw<ArgumentException>().WithMessage("A440 is in the read-only*");
        Ensure("A447.01", 1, protocol, forWrite: true).Should().Throw<ArgumentException>();
        Ensure("A447", 1, protocol, forWrite: false).Should().NotThrow();
        Ensure("A448", 1, protocol, forWrite: true).Should().NotThrow();
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void C_mode_cannot_reach_the_work_area(bool forWrite)
    {
        Ensure("W30", 1, HostLinkCommandSet.CMode, forWrite).Should().Throw<ArgumentException>()
            .WithMessage("W30: the work area (W) is not reachable with C-mode commands; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, or go through a FINS view of the unit, such as plc.Unit(0, HostLinkCommandSet.Fins).");
        Ensure("W30.06", 1, HostLinkCommandSet.CMode, forWrite).Should().Throw<ArgumentException>().WithMessage("W30.06: *use FINS*");
        Ensure("W30", 1, HostLinkCommandSet.Fins, forWrite).Should().NotThrow();
    }

    [Theory]
    [InlineData("D10000", 1, false, "D10000 is beyond the DM area (0–9999) reachable with C-mode RD; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("D10000", 1, true, "D10000 is beyond the DM area (0–9999) reachable with C-mode WD; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("D32767.05", 1, false, "D32767 is beyond the DM area (0–9999) reachable with C-mode RD; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("D9995", 10, false, "10 words from D9995 reach D10004, beyond the DM area (0–9999) reachable with C-mode RD; transfer fewer words, or use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("E3_10000", 1, false, "E3_10000 is beyond the EM area (0–9999) reachable with C-mode RE; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("E3_9999", 2, true, "2 words from E3_9999 reach E3_10000, beyond the EM area (0–9999) reachable with C-mode WE*")]
    [InlineData("T2048", 1, false, "T2048 is beyond the timer numbers (0–2047) reachable with C-mode RC; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("C2048", 1, true, "C2048 is beyond the counter numbers (0–2047) reachable with C-mode WC; use FINS: set HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins, *")]
    [InlineData("C2000", 100, false, "100 words from C2000 reach C2099, beyond the counter numbers (0–2047)*")]
    public void C_mode_limits_are_named_in_the_message(string address, int count, bool forWrite, string message)
    {
        Ensure(address, count, HostLinkCommandSet.CMode, forWrite).Should().Throw<ArgumentOutOfRangeException>().WithMessage(message);
        Ensure(address, count, HostLinkCommandSet.Fins, forWrite).Should().NotThrow("FINS reaches the whole area");
    }

    [Fact]
    public void An_undefined_protocol_is_rejected() =>
        Ensure("D0", 1, (HostLinkCommandSet)7).Should().Throw<ArgumentOutOfRangeException>().Which.ParamName.Should().Be("commandSet");
}
