using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// What a C200H/CQM1/CPM1 programmer writes goes out as the C-mode command the manuals give for that area (C200HS 11-3:
/// RR for IR/SR, RL for LR, RH for HR, RC for TC, RD for DM, RJ for AR; WR/WL/WH/WC/WD/WJ to write), with the word the
/// programmer wrote as its begin word, and reads right from a simulator emulating the model.
/// </summary>
public sealed class OlderFamilyCommandTests
{
    [Theory]
    [InlineData("C200HS", "IR010", "@00RR00100001")]
    [InlineData("C200HS", "SR250", "@00RR02500001")]
    [InlineData("C200HS", "LR10", "@00RL00100001")]
    [InlineData("C200HS", "HR05", "@00RH00050001")]
    [InlineData("C200HS", "TC5", "@00RC00050001")]
    [InlineData("C200HS", "C5", "@00RC00050001")]
    [InlineData("C200HS", "DM0100", "@00RD01000001")]
    [InlineData("C200HS", "AR10", "@00RJ00100001")]
    [InlineData("CPM1A", "SR250", "@00RR02500001")]
    [InlineData("CPM1A", "LR15", "@00RL00150001")]
    [InlineData("CQM1", "TC511", "@00RC05110001")]
    // On CS/CJ counters are RC entries 2048 + n (W342 p128), LR n is RL n (CIO 1000 + n).
    [InlineData("CS1", "C5", "@00RC20530001")]
    [InlineData("CS1", "LR10", "@00RL00100001")]
    public async Task An_older_family_address_is_read_with_its_areas_C_mode_command(string model, string address, string command)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        plc.WriteWords(address, [0x2468]);
        await using var line = EmulatedLine.Start(plc, model);

        (await line.Client.ReadWordsAsync(address, 1)).Should().Equal((ushort)0x2468);

        line.SentFrames.Should().ContainSingle().Which.Should().StartWith(command);
    }

    [Theory]
    [InlineData("C200HS", "IR010", "@00WR0010ABCD")]
    [InlineData("C200HS", "LR10", "@00WL0010ABCD")]
    [InlineData("C200HS", "HR05", "@00WH0005ABCD")]
    [InlineData("C200HS", "DM0100", "@00WD0100ABCD")]
    [InlineData("C200HS", "AR10", "@00WJ0010ABCD")]
    [InlineData("C200HS", "TC5", "@00WC0005ABCD")]
    public async Task An_older_family_address_is_written_with_its_areas_C_mode_command(string model, string address, string command)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model, InitialMode = PlcMode.Program });
        await using var line = EmulatedLine.Start(plc, model);

        await line.Client.WriteWordsAsync(address, new ushort[] { 0xABCD });

        line.SentFrames.Should().ContainSingle().Which.Should().StartWith(command);
        (await line.Client.ReadWordsAsync(address, 1)).Should().Equal((ushort)0xABCD);
    }

    [Fact]
    public async Task A_bit_of_an_LR_word_is_read_with_RL()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc.WriteWords("LR10", [0x0020]);
        await using var line = EmulatedLine.Start(plc, "CPM1A");

        (await line.Client.ReadBitAsync("LR10.05")).Should().BeTrue();

        line.SentFrames.Should().ContainSingle().Which.Should().StartWith("@00RL00100001");
    }
}
