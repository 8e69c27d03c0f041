using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// One answer for bits on a C-mode client: C-mode has no bit write and cannot reach the work area, so a C-mode client
/// refuses the bit writes and the W reads it cannot make — before anything is sent — and every refusal says exactly how
/// to switch. A FINS view writes and reads back the same bits.
/// </summary>
public sealed class BitCommandSetTests
{
    private const string SetOption = "HostLinkClientOptions.CommandSet = HostLinkCommandSet.Fins";

    [Fact]
    public async Task A_C_mode_client_refuses_to_write_W400_07_and_to_read_it_alike_and_sends_nothing()
    {
        await using InProcessLine line = InProcessLine.Start();

        var write = await FluentActions.Awaiting(() => line.Client.WriteBitAsync("W400.07", true)).Should().ThrowAsync<ArgumentException>();
        var read = await FluentActions.Awaiting(() => line.Client.ReadBitAsync("W400.07")).Should().ThrowAsync<ArgumentException>();

        write.Which.Message.Should().Contain("C-mode has no bit write").And.Contain(SetOption).And.Contain("plc.Unit(0, HostLinkCommandSet.Fins)")
            .And.NotContain("AllowReadModifyWriteBits", "C-mode cannot reach W at all, so reading and writing the word back is no way either");
        read.Which.Message.Should().Contain("work area").And.Contain(SetOption).And.Contain("plc.Unit(0, HostLinkCommandSet.Fins)");
        line.FramesSent.Should().Be(0);
        line.Plc.GetBit("W400.07").Should().BeFalse();
    }

    [Fact]
    public async Task A_C_mode_client_refuses_a_CIO_bit_write_naming_FINS_and_read_modify_write_for_its_own_unit()
    {
        await using InProcessLine line = InProcessLine.Start();

        var single = await FluentActions.Awaiting(() => line.Client.Unit(3).WriteBitAsync("CIO 10.03", true)).Should().ThrowAsync<ArgumentException>();
        var several = await FluentActions.Awaiting(() => line.Client.WriteBitsAsync(PlcAddress.Parse("H5.15"), new[] { true, true })).Should().ThrowAsync<ArgumentException>();
        var generic = await FluentActions.Awaiting(() => line.Client.WriteAsync("CIO 10.03", true)).Should().ThrowAsync<ArgumentException>();

        single.Which.Message.Should().Contain("CIO10.03").And.Contain(SetOption).And.Contain("plc.Unit(3, HostLinkCommandSet.Fins)")
            .And.Contain("HostLinkClientOptions.AllowReadModifyWriteBits = true").And.Contain("CIO10");
        several.Which.Message.Should().Contain("2 bits from H5.15").And.Contain("H5-H6").And.Contain(SetOption);
        generic.Which.Message.Should().Contain("C-mode has no bit write");
        line.FramesSent.Should().Be(0);
    }

    [Fact]
    public async Task A_FINS_view_writes_W400_07_and_reads_it_back()
    {
        await using InProcessLine line = InProcessLine.Start();
        HostLinkUnit fins = line.Client.Unit(0, HostLinkCommandSet.Fins);

        await fins.WriteBitAsync("W400.07", true);

        line.Plc.GetBit("W400.07").Should().BeTrue();
        (await fins.ReadBitAsync("W400.07")).Should().BeTrue();
        (await fins.ReadBitAsync("W400.06")).Should().BeFalse();
    }

    [Fact]
    public async Task A_FINS_client_writes_and_reads_bits_of_every_area()
    {
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { CommandSet = HostLinkCommandSet.Fins });

        foreach (string bit in new[] { "CIO 10.03", "W400.07", "H5.15", "D100.00" })
        {
            await line.Client.WriteBitAsync(bit, true);
            (await line.Client.ReadBitAsync(bit)).Should().BeTrue(bit);
            line.Plc.GetBit(bit.Replace(" ", "", StringComparison.Ordinal)).Should().BeTrue(bit);
        }
    }

    [Fact]
    public async Task A_C_mode_client_that_allows_read_modify_write_writes_and_reads_a_CIO_bit_with_C_mode_only()
    {
        await using InProcessLine line = InProcessLine.Start(new HostLinkClientOptions { AllowReadModifyWriteBits = true });
        line.Plc.WriteWords("CIO10", new ushort[] { 0x0101 });
        var headers = new List<string>();
        line.Client.FrameObserver = (sent, frame) =>
        {
            if (sent)
            {
                headers.Add(System.Text.Encoding.ASCII.GetString(frame.Span.Slice(3, 2)));
            }
        };

        await line.Client.WriteBitAsync("CIO 10.03", true);

        (await line.Client.ReadBitAsync("CIO 10.03")).Should().BeTrue();
        line.Plc.ReadWords("CIO10", 1).Should().Equal((ushort)0x0109);
        headers.Should().Equal("RR", "WR", "RR");
    }
}
