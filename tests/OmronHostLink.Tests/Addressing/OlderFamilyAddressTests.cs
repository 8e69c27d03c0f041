using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Addressing;

/// <summary>
/// What a C200H/CQM1/CPM1 programmer writes: IR and SR words are CIO words, LR is its own area (C-mode RL/WL), TC is the
/// shared timer/counter space, DM/HR/AR take leading zeros.
/// </summary>
public sealed class OlderFamilyAddressTests
{
    [Theory]
    [InlineData("LR10", PlcArea.Link, 10, -1, "LR10")]
    [InlineData("lr 63", PlcArea.Link, 63, -1, "LR63")]
    [InlineData("LR10.05", PlcArea.Link, 10, 5, "LR10.05")]
    [InlineData("LR199", PlcArea.Link, 199, -1, "LR199")]
    [InlineData("IR010", PlcArea.Cio, 10, -1, "CIO10")]
    [InlineData("IR010.03", PlcArea.Cio, 10, 3, "CIO10.03")]
    [InlineData("SR250", PlcArea.Cio, 250, -1, "CIO250")]
    [InlineData("TC5", PlcArea.Timer, 5, -1, "T5")]
    [InlineData("TC511", PlcArea.Timer, 511, -1, "T511")]
    [InlineData("DM0100", PlcArea.Dm, 100, -1, "D100")]
    [InlineData("HR05", PlcArea.Holding, 5, -1, "H5")]
    [InlineData("AR10", PlcArea.Auxiliary, 10, -1, "A10")]
    public void Older_family_spellings_parse(string text, PlcArea area, int word, int bit, string canonical)
    {
        var address = PlcAddress.Parse(text);

        address.Area.Should().Be(area);
        address.Word.Should().Be(word);
        address.Bit.Should().Be(bit);
        address.ToString().Should().Be(canonical);
        PlcAddress.Parse(canonical).Should().Be(address);
    }

    [Theory]
    [InlineData("LR200", "outside the LR area (LR0–LR199)")]
    [InlineData("TC5.01", "cannot take a bit")]
    [InlineData("LR", "missing")]
    public void Older_family_spellings_are_checked(string text, string reason)
    {
        FluentActions.Invoking(() => PlcAddress.Parse(text)).Should().Throw<FormatException>().WithMessage($"*{reason}*");
    }

    [Fact]
    public void LR_maps_to_the_C_mode_LR_area_and_to_CIO_1000_plus_n_in_FINS()
    {
        CModeAddressing.Map(PlcAddress.Parse("LR10")).Should().Be((CModeArea.Lr, 10));
        CModeAreaInfo.ReadHeader(CModeAddressing.AreaOf(PlcArea.Link)).Should().Be("RL");
        CModeAreaInfo.WriteHeader(CModeAddressing.AreaOf(PlcArea.Link)).Should().Be("WL");

        // W342: LR n is CIO 1000 + n on CS/CJ, which FINS addresses as CIO.
        var fins = FinsAddressing.Word(PlcAddress.Parse("LR10"));
        fins.Should().Be(FinsAddressing.Word(PlcAddress.Parse("CIO1010")));
    }

    [Fact]
    public async Task Reading_LR10_sends_RL_with_begin_word_0010()
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        await using var plc = new ScriptedPlc(plcEnd, f => f.StartsWith("@00RL00100001", StringComparison.Ordinal)
            ? new Reply(TestFrames.Final("@00RL00" + "1234"))
            : null);
        await using var client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine, ReadRetries = 0 });

        var words = await client.ReadWordsAsync("LR10", 1);

        words.Should().Equal((ushort)0x1234);
        plc.Received.Should().ContainSingle(f => f.StartsWith("@00RL00100001", StringComparison.Ordinal));
    }

    [Fact]
    public async Task LR_words_written_with_WL_are_the_CIO_1000_words_of_a_CS_CJ_simulator()
    {
        var plc = new VirtualPlc();
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        using var stop = new CancellationTokenSource();
        _ = plc.RunAsync(plcEnd, stop.Token);
        await using (var client = HostLinkClient.ForStream(host, new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), TurnaroundAllowance = Allowances.LosslessLine }))
        {
            await client.WriteWordsAsync("LR10", new ushort[] { 0xBEEF, 0x0102 });

            plc.ReadWords(PlcArea.Cio, 1010, 2).Should().Equal((ushort)0xBEEF, (ushort)0x0102);
            (await client.ReadWordsAsync("LR11", 1)).Should().Equal((ushort)0x0102);
        }

        stop.Cancel();
    }
}
