using System.Globalization;
using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// Every profile's memory, edge by edge, as the manuals give it (docs/models.md), written here by hand and not read from
/// the profiles: the first and last word of each range read right through a client checked against the model, from the
/// simulator emulating it; the word one past the last is refused before anything is sent, and the emulated PLC answers
/// a C-mode read of it as its manual says (end code 15, or 0000 where the manual says it reads 0000).
/// </summary>
public sealed class ModelEdgeTableTests
{
    /// <summary>What lies one past the last word of a range.</summary>
    public enum Past
    {
        /// <summary>Memory the model lacks; its C-mode read is answered with end code 15 (entry number data error).</summary>
        EndCode15,

        /// <summary>Memory the model lacks but its manual says a C-mode read answers with 0000 and end code 00: the hazard.</summary>
        ReadsZero,

        /// <summary>Beyond C-mode's reach (D10000 and up): only FINS could name it, and the simulator does not narrow FINS.</summary>
        FinsOnly,

        /// <summary>No such address at all (beyond the CS/CJ address space): refused when parsed.</summary>
        NoAddress,
    }

    // The older families: timers and counters share one TC number space (RC entry n is TC n).
    private static readonly HashSet<string> SharedTimerCounterNumbers =
        ["C200H", "C200HS", "C200HX", "CQM1", "CQM1H", "CQM1H-CPU61", "CPM1A", "SRM1", "CPM2A"];

    /// <summary>Model, first word, last word, the word one past the last, and what that word is.</summary>
    public static TheoryData<string, string, string, string, Past> Edges()
    {
        var rows = new TheoryData<string, string, string, string, Past>();

        // C200H: no C200H manual page was found; the profile's assumed ranges (unverified), DM the part of code 12's three.
        rows.Add("C200H", "CIO0", "CIO255", "CIO256", Past.EndCode15);
        rows.Add("C200H", "LR0", "LR63", "LR64", Past.EndCode15);
        rows.Add("C200H", "H0", "H99", "H100", Past.EndCode15);
        rows.Add("C200H", "A0", "A27", "A28", Past.EndCode15);
        rows.Add("C200H", "T0", "T511", "T512", Past.EndCode15);
        rows.Add("C200H", "C0", "C511", "C512", Past.EndCode15);
        rows.Add("C200H", "D0", "D1999", "D2000", Past.EndCode15);

        // C200HS Operation Manual 11-3: RR/WR 0000–0511 (p410), RL/WL 0000–0063 (p411), RH 0000–0099 and RC 0000–0511
        // (p408), RJ 0000–0027 (p410), RD: DM 6656–6999 do not exist and read 0000 without an error (p409 note 2).
        foreach (string model in new[] { "C200HS", "C200HX" })
        {
            // C200HX/HG/HE Operation Manual 10-3: the same ranges (RR 0000–0511, RD note: 6656–6999 read 0000, p463).
            rows.Add(model, "CIO0", "CIO511", "CIO512", Past.EndCode15);
            rows.Add(model, "LR0", "LR63", "LR64", Past.EndCode15);
            rows.Add(model, "H0", "H99", "H100", Past.EndCode15);
            rows.Add(model, "A0", "A27", "A28", Past.EndCode15);
            rows.Add(model, "T0", "T511", "T512", Past.EndCode15);
            rows.Add(model, "C0", "C511", "C512", Past.EndCode15);
            rows.Add(model, "D0", "D6655", "D6656", Past.ReadsZero);
        }

        // CQM1: CQM1/CPM1/CPM1A/SRM1 Programming Manual p388 (QQ table: IR/SR 0000–0255, LR 0–63, HR 0–99, AR 0–27,
        // TIM/CNT 0–511, DM 0–6655). CQM1H Programming Manual p470: the same, and EM 0000–6143 on the CPU61 only.
        foreach (string model in new[] { "CQM1", "CQM1H", "CQM1H-CPU61" })
        {
            rows.Add(model, "CIO0", "CIO255", "CIO256", Past.EndCode15);
            rows.Add(model, "LR0", "LR63", "LR64", Past.EndCode15);
            rows.Add(model, "H0", "H99", "H100", Past.EndCode15);
            rows.Add(model, "A0", "A27", "A28", Past.EndCode15);
            rows.Add(model, "T0", "T511", "T512", Past.EndCode15);
            rows.Add(model, "C0", "C511", "C512", Past.EndCode15);
            rows.Add(model, "D0", "D6655", "D6656", Past.EndCode15);
        }

        rows.Add("CQM1H-CPU61", "E0_0", "E0_6143", "E0_6144", Past.EndCode15);

        // CPM1/CPM1A and SRM1: the same manual p388 (QQ: IR/SR 0000–0019 and 0200–0255, LR 0–15, HR 0–19, AR 0–15,
        // TIM/CNT 0–127, DM 0–1023 and 6144–6655) and p369 (RD note 1: DM 1024–6143 on the CPM1/CPM1A, 2048–6143 on the
        // SRM1, read 0000).
        foreach ((string model, int lastDm) in new[] { ("CPM1A", 1023), ("SRM1", 2047) })
        {
            rows.Add(model, "CIO0", "CIO19", "CIO20", Past.EndCode15);
            rows.Add(model, "CIO200", "CIO255", "CIO256", Past.EndCode15);
            rows.Add(model, "LR0", "LR15", "LR16", Past.EndCode15);
            rows.Add(model, "H0", "H19", "H20", Past.EndCode15);
            rows.Add(model, "A0", "A15", "A16", Past.EndCode15);
            rows.Add(model, "T0", "T127", "T128", Past.EndCode15);
            rows.Add(model, "C0", "C127", "C128", Past.EndCode15);
            rows.Add(model, "D0", $"D{lastDm}", $"D{lastDm + 1}", Past.ReadsZero);
            rows.Add(model, "D6144", "D6655", "D6656", Past.EndCode15);
        }

        // CPM2A/CPM2C: W353 p285 (WR: 0000–0049 and 0200–0252; WL: 0000–0015). HR, AR, TC and DM: no manual page was
        // found (unverified: HR 0–19, AR 0–23, TC 0–255, DM 0–2047 and 6144–6655, 2048–6143 read 0000 as on the SRM1).
        rows.Add("CPM2A", "CIO0", "CIO49", "CIO50", Past.EndCode15);
        rows.Add("CPM2A", "CIO200", "CIO255", "CIO256", Past.EndCode15);
        rows.Add("CPM2A", "LR0", "LR15", "LR16", Past.EndCode15);
        rows.Add("CPM2A", "H0", "H19", "H20", Past.EndCode15);
        rows.Add("CPM2A", "A0", "A23", "A24", Past.EndCode15);
        rows.Add("CPM2A", "T0", "T255", "T256", Past.EndCode15);
        rows.Add("CPM2A", "C0", "C255", "C256", Past.EndCode15);
        rows.Add("CPM2A", "D0", "D2047", "D2048", Past.ReadsZero);
        rows.Add("CPM2A", "D6144", "D6655", "D6656", Past.EndCode15);

        // CP1E/CP1L/CP1H/CP2E: the memory-area pages were not found; the CS/CJ bounds (W342 p128, 5-2-2), with DM as
        // the profiles assume it (unverified): CP1E E-type D0–D2047, N/NA-type D0–D8191, CP1L L-type D0–D9999 and
        // D32000–D32767. No EM on any of them; no LR on the CP1E and CP2E (W614 lists no RL).
        foreach (string model in new[] { "CP1E-E", "CP1E-N", "CP2E", "CP1L-L", "CP1L-M", "CP1H", "CS1" })
        {
            rows.Add(model, "CIO0", "CIO6143", "CIO6144", Past.NoAddress);
            rows.Add(model, "W0", "W511", "W512", Past.NoAddress);
            rows.Add(model, "H0", "H511", "H512", Past.NoAddress);
            rows.Add(model, "A0", "A959", "A960", Past.NoAddress);
            rows.Add(model, "T0", "T4095", "T4096", Past.NoAddress);
            rows.Add(model, "C0", "C4095", "C4096", Past.NoAddress);
        }

        rows.Add("CP1E-E", "D0", "D2047", "D2048", Past.EndCode15);
        rows.Add("CP1E-N", "D0", "D8191", "D8192", Past.EndCode15);
        rows.Add("CP2E", "D0", "D32767", "D32768", Past.NoAddress);
        rows.Add("CP1L-L", "D0", "D9999", "D10000", Past.FinsOnly);
        rows.Add("CP1L-L", "D32000", "D32767", "D32768", Past.NoAddress);
        foreach (string model in new[] { "CP1L-L", "CP1L-M", "CP1H", "CS1" })
        {
            rows.Add(model, "LR0", "LR199", "LR200", Past.NoAddress);
        }

        rows.Add("CP1L-M", "D0", "D32767", "D32768", Past.NoAddress);
        rows.Add("CP1H", "D0", "D32767", "D32768", Past.NoAddress);

        // CS1/CJ1/CJ2: W342 p128 and 5-2-2: D0–D32767, EM banks 0–C of 32768 words (which exist depends on the CPU).
        rows.Add("CS1", "D0", "D32767", "D32768", Past.NoAddress);
        rows.Add("CS1", "E0_0", "E0_32767", "E0_32768", Past.NoAddress);
        rows.Add("CS1", "EC_0", "EC_32767", "ED_0", Past.NoAddress);
        return rows;
    }

    /// <summary>Areas a model does not have at all, and what its C-mode read gets from the emulated PLC (null: no C-mode command names it).</summary>
    public static TheoryData<string, string, string?> AbsentAreas()
    {
        return new TheoryData<string, string, string?>
        {
            // The older families have no work area (W exists only on CS/CJ/CP; no C-mode command names it, W342 p128 note 1).
            { "C200HS", "W0", null },
            { "CPM1A", "W0", null },
            { "CQM1", "W0", null },

            // No EM: RE is not in their command lists, so the PLC answers IC.
            { "C200HS", "E0_0", "IC" },
            { "CQM1", "E0_0", "IC" },
            { "CPM1A", "E0_0", "IC" },
            { "CP1H", "E0_0", "IC" },
            { "CP2E", "E0_0", "IC" },

            // The C200HX lists RE, and an EM bank its CPU lacks reads 0000 (C200HX p465): refused, whatever the CPU.
            { "C200HX", "E0_0", "0000" },

            // No LR on the CP2E and CP1E: RL is not in W614's list.
            { "CP2E", "LR0", "IC" },
            { "CP1E-E", "LR0", "IC" },
        };
    }

    [Fact]
    public void The_edge_table_names_every_profile_and_exactly_the_areas_each_has()
    {
        var table = Edges().Select(row => ((string)row[0], PlcAddress.Parse((string)row[1]).Area)).ToHashSet();

        foreach (PlcModelProfile profile in PlcModelProfile.All)
        {
            var areas = profile.Areas.Select(r => r.Area).Distinct().ToHashSet();
            table.Where(t => t.Item1 == profile.Name).Select(t => t.Area).Should().BeEquivalentTo(areas, $"the table lists every area of {profile.Name}, and only those");
        }

        table.Select(t => t.Item1).Distinct().Should().BeEquivalentTo(PlcModelProfile.All.Select(p => p.Name));
    }

    [Theory]
    [MemberData(nameof(Edges))]
    public async Task The_first_and_last_word_read_right_and_the_next_is_refused_before_the_wire(string model, string first, string last, string past, Past what)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using var line = EmulatedLine.Start(plc, model);

        ushort value = 0x4100;
        foreach (string address in new[] { first, last })
        {
            value++;
            plc.WriteWords(address, [value]);
            HostLinkUnit unit = line.Client.Unit(0, CommandSetFor(address));
            (await unit.ReadWordsAsync(address, 1)).Should().Equal(new[] { value }, $"a {model} has {address}");
        }

        long sent = line.BytesSent;
        HostLinkUnit pastUnit = line.Client.Unit(0, what == Past.FinsOnly ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode);
        Exception refusal = (await FluentActions.Awaiting(() => pastUnit.ReadWordsAsync(past, 1)).Should().ThrowAsync<Exception>()).Which;
        (refusal is ArgumentException or FormatException).Should().BeTrue($"{past} is refused as an address ({refusal.GetType().Name}: {refusal.Message})");
        if (what is Past.EndCode15 or Past.ReadsZero or Past.FinsOnly)
        {
            refusal.Message.Should().StartWith($"{past} is beyond the").And.Contain(PlcModelProfile.Parse(model).DisplayName);
        }

        line.BytesSent.Should().Be(sent, $"the read of {past} is refused before anything is sent");
    }

    [Theory]
    [MemberData(nameof(Edges))]
    public async Task The_emulated_PLC_answers_a_read_of_the_next_word_as_its_manual_says(string model, string first, string last, string past, Past what)
    {
        _ = first;
        _ = last;
        if (what is Past.FinsOnly or Past.NoAddress)
        {
            return; // no C-mode read names it
        }

        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        plc.WriteWords(past, [0x5A5A]); // memory behind the check holds a value: 0000 must come from the emulation
        await using RawHost raw = RawHost.Start(plc);
        (string header, string text) = CModeRead(model, past);

        string answer = await raw.TransactAsync(RawHost.Command("@00" + header + text));

        answer.Should().Be(RawHost.Command("@00" + header + (what == Past.ReadsZero ? "000000" : "15")), $"a {model} answers a read of {past} so");
    }

    [Theory]
    [MemberData(nameof(AbsentAreas))]
    public async Task An_area_the_model_lacks_is_refused_before_the_wire_and_the_emulated_PLC_answers_as_it_would(string model, string address, string? plcAnswer)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using (var line = EmulatedLine.Start(plc, model))
        {
            PlcModelProfile profile = PlcModelProfile.Parse(model);
            HostLinkUnit unit = line.Client.Unit(0, CommandSetFor(address));

            var refusal = await FluentActions.Awaiting(() => unit.ReadWordsAsync(address, 1)).Should().ThrowAsync<Exception>();

            (refusal.Which is ArgumentException or NotSupportedException).Should().BeTrue(refusal.Which.Message);
            refusal.Which.Message.Should().Contain(profile.DisplayName);
            line.BytesSent.Should().Be(0);
        }

        if (plcAnswer is null)
        {
            return;
        }

        plc.WriteWords(address, [0x5A5A]);
        await using RawHost raw = RawHost.Start(plc);
        (string header, string text) = CModeRead(model, address);
        string expected = plcAnswer == "IC" ? RawHost.Command("@00IC") : RawHost.Command("@00" + header + "00" + plcAnswer);
        (await raw.TransactAsync(RawHost.Command("@00" + header + text))).Should().Be(expected);
    }

    [Theory]
    // CIO 253–255 cannot be written by a host: C200HS p410 (WR note), CQM1/CPM1 p369 and W353 p285 (WR to 0252).
    [InlineData("C200HS", "CIO252", true)]
    [InlineData("C200HS", "CIO253", false)]
    [InlineData("C200HS", "CIO255", false)]
    [InlineData("C200HS", "CIO256", true)]
    [InlineData("CQM1", "CIO253", false)]
    [InlineData("CPM1A", "CIO252", true)]
    [InlineData("CPM1A", "CIO253", false)]
    [InlineData("CPM2A", "CIO253", false)]
    // CS/CJ: A0–A447 are read-only (W342 5-2-2). The C-series AR words are written with WJ (C200HS 11-3, CPM-Q 6-3).
    [InlineData("CS1", "A447", false)]
    [InlineData("CS1", "A448", true)]
    [InlineData("C200HS", "A10", true)]
    [InlineData("CPM1A", "A15", true)]
    public async Task Writes_to_read_only_words_are_refused_before_the_wire(string model, string address, bool writable)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using var line = EmulatedLine.Start(plc, model);

        Func<Task> write = () => line.Client.WriteWordsAsync(address, new ushort[] { 0x1234 });

        if (writable)
        {
            await write();
            plc.ReadWord(PlcAddress.Parse(address).Area, PlcAddress.Parse(address).Word).Should().Be(0x1234);
            return;
        }

        (await write.Should().ThrowAsync<ArgumentException>()).Which.Message
            .Should().StartWith(address).And.Contain("read-only");
        line.BytesSent.Should().Be(0);
    }

    // C-mode where the manual says C-mode reaches (W342 p128: no W; D and EM to 9999; T and C to 2047); FINS beyond.
    private static HostLinkCommandSet CommandSetFor(string address)
    {
        PlcAddress a = PlcAddress.Parse(address);
        bool cmode = a.Area switch
        {
            PlcArea.Work => false,
            PlcArea.Dm or PlcArea.Em => a.Word < 10000,
            PlcArea.Timer or PlcArea.Counter => a.Word < 2048,
            _ => true,
        };
        return cmode ? HostLinkCommandSet.CMode : HostLinkCommandSet.Fins;
    }

    // The C-mode read of one word, written from the manuals' command formats (header, beginning word, count).
    private static (string Header, string Text) CModeRead(string model, string address)
    {
        PlcAddress a = PlcAddress.Parse(address);
        string word = a.Word.ToString("D4", CultureInfo.InvariantCulture);
        return a.Area switch
        {
            PlcArea.Cio => ("RR", word + "0001"),
            PlcArea.Link => ("RL", word + "0001"),
            PlcArea.Holding => ("RH", word + "0001"),
            PlcArea.Auxiliary => ("RJ", word + "0001"),
            PlcArea.Timer => ("RC", word + "0001"),
            PlcArea.Counter => ("RC", (SharedTimerCounterNumbers.Contains(model) ? a.Word : 2048 + a.Word).ToString("D4", CultureInfo.InvariantCulture) + "0001"),
            PlcArea.Dm => ("RD", word + "0001"),
            PlcArea.Em => ("RE", a.Bank.ToString("X2", CultureInfo.InvariantCulture) + word + "0001"),
            _ => throw new ArgumentException($"No C-mode read names {address}."),
        };
    }
}
