using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// A client with <c>Model = "auto"</c> against the simulator emulating each model: the first use asks MM once, the code
/// the manual gives names the family, and what that family lacks is refused before the wire from then on.
/// </summary>
public sealed class ModelDetectionTests
{
    /// <summary>
    /// Model, the code its MM answer carries (W342 p141, C200HX p490, W353 p300, CQM1/CPM1 manual p386; empty where no
    /// manual found gives one or the model has no MM), and an address the detected family does not have (empty: none
    /// to show, the family being the CS/CJ or unknown).
    /// </summary>
    public static TheoryData<string, string, string> Families() => new()
    {
        // 12: C20H/C28H/C40H, C200H, C200HS, C200HX/HG/HE. Their common part has DM 0–1999 only.
        { "C200H", "12", "D2000" },
        { "C200HS", "12", "D6656" },
        { "C200HX", "12", "D2000" },

        // 11: C2000H, CQM1, CPM1/CPM1A, CPM2A/CPM2C, SRM1(-V2). Their common part: DM 0–1023 and 6144–6655, CIO 0–19 and 200–255.
        { "CQM1", "11", "D1024" },
        { "CQM1H", "11", "D1024" },
        { "CQM1H-CPU61", "11", "CIO20" },
        { "CPM1A", "11", "D1024" },
        { "SRM1", "11", "D2048" },
        { "CPM2A", "11", "LR16" },

        // 30: CS/CJ.
        { "CS1", "30", "" },

        // No MM code in a manual found (CP1L, CP1H: the simulator answers IC rather than invent one); no MM at all (CP1E, CP2E: W614).
        { "CP1E-E", "", "" },
        { "CP1E-N", "", "" },
        { "CP2E", "", "" },
        { "CP1L-L", "", "" },
        { "CP1L-M", "", "" },
        { "CP1H", "", "" },
    };

    [Fact]
    public void The_family_table_names_every_profile()
    {
        Families().Select(row => (string)row[0]).Should().BeEquivalentTo(PlcModelProfile.All.Select(p => p.Name));
    }

    [Theory]
    [MemberData(nameof(Families))]
    public async Task The_first_use_asks_MM_once_and_the_family_it_names_is_checked_from_then_on(string model, string code, string lacked)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        plc.WriteWord(PlcArea.Dm, 0, 0x1357);
        await using var line = EmulatedLine.Start(plc, "auto");

        (await line.Client.ReadWordsAsync("D0", 1)).Should().Equal((ushort)0x1357);

        line.SentFrames.Should().HaveCount(2);
        line.SentFrames[0].Should().StartWith("@00MM", "the first use asks the model first");
        line.SentFrames[1].Should().StartWith("@00RD00000001");
        PlcModelProfile? detected = await line.Client.GetModelProfileAsync();
        line.SentFrames.Should().HaveCount(2, "MM is asked once per unit");
        await line.Client.ReadWordsAsync("D0", 1);
        line.SentFrames.Should().HaveCount(3);

        if (code.Length == 0)
        {
            detected.Should().BeNull($"a {model} names no family by MM");
            return;
        }

        byte mm = Convert.ToByte(code, 16);
        detected.Should().NotBeNull();
        detected!.ModelCode.Should().Be(mm);
        if (mm == 0x30)
        {
            detected.Should().BeSameAs(PlcModelProfile.Parse("CS1"));
        }
        else
        {
            detected.DisplayName.Should().Contain(PlcModelProfile.Parse(model).DisplayName, "the family named says which models it covers");
        }

        if (lacked.Length > 0)
        {
            long sent = line.BytesSent;
            (await FluentActions.Awaiting(() => line.Client.ReadWordsAsync(lacked, 1)).Should().ThrowAsync<ArgumentOutOfRangeException>())
                .Which.Message.Should().StartWith($"{lacked} is beyond the").And.Contain($"PLC answering MM {code}");
            line.BytesSent.Should().Be(sent);
        }
    }
}
