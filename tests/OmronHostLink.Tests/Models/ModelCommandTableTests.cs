using OmronHostLink.Simulator;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// What each profile accepts beyond the area reads, written here by hand from the manuals (docs/models.md): FINS over
/// Host Link, the compound read QQ, MM and XZ. What a model has works against the simulator emulating it; what it lacks
/// is refused before anything is sent, and the emulated PLC answers it with IC as the real one does.
/// </summary>
public sealed class ModelCommandTableTests
{
    /// <summary>Model, whether it takes FINS (FA), whether it has QQ, whether it has MM and XZ.</summary>
    public static TheoryData<string, bool, bool, bool> Commands() => new()
    {
        // C200H: its manual was not found; the C200HS's list without QQ is assumed (unverified).
        { "C200H", false, false, true },

        // C200HS Operation Manual 11-3: QQ p428 (11-3-33), XZ p429, MM p? (code 12 in W342 p141); no FINS on the C series.
        { "C200HS", false, true, true },

        // C200HX/HG/HE 10-3: MM p490; its QQ page was not found (not assumed).
        { "C200HX", false, false, true },

        // CQM1: CQM1/CPM1/CPM1A/SRM1 Programming Manual 6-3: QQ p388, MM p386. CQM1H: end code table p441, QQ p470.
        { "CQM1", false, true, true },
        { "CQM1H", false, true, true },
        { "CQM1H-CPU61", false, true, true },

        // CPM1/CPM1A, SRM1: p388 (QQ), p386 (MM). CPM2A/CPM2C: W353 4-5-30 QQ (p302), 4-5-26 MM (p300).
        { "CPM1A", false, true, true },
        { "SRM1", false, true, true },
        { "CPM2A", false, true, true },

        // CP2E: W614 p14-40 lists FINS and the C-mode commands RR…TS, without QQ, MM or XZ; the CP1E is assumed the same.
        { "CP1E-E", true, false, false },
        { "CP1E-N", true, false, false },
        { "CP2E", true, false, false },

        // CP1L/CP1H: no manual page found; FINS and the CS/CJ C-mode list with QQ assumed (unverified).
        { "CP1L-L", true, true, true },
        { "CP1L-M", true, true, true },
        { "CP1H", true, true, true },

        // CS1/CJ1/CJ2: W342 sections 4 (QQ p168, MM p141) and 5 (FINS).
        { "CS1", true, true, true },
    };

    [Fact]
    public void The_command_table_names_every_profile()
    {
        Commands().Select(row => (string)row[0]).Should().BeEquivalentTo(PlcModelProfile.All.Select(p => p.Name));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task FINS_is_used_where_the_model_takes_it_and_refused_before_the_wire_where_not(string model, bool fins, bool qq, bool mmXz)
    {
        _ = qq;
        _ = mmXz;
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        plc.WriteWord(PlcArea.Dm, 0, 0x4321);
        await using var line = EmulatedLine.Start(plc, model);
        HostLinkUnit unit = line.Client.Unit(0, HostLinkCommandSet.Fins);

        if (fins)
        {
            (await unit.ReadWordsAsync("D0", 1)).Should().Equal((ushort)0x4321);
            return;
        }

        await FluentActions.Awaiting(() => unit.ReadWordsAsync("D0", 1)).Should().ThrowAsync<NotSupportedException>()
            .WithMessage($"*{PlcModelProfile.Parse(model).DisplayName} does not take FINS*");
        await FluentActions.Awaiting(() => unit.ReadCpuStatusAsync()).Should().ThrowAsync<NotSupportedException>();
        await FluentActions.Awaiting(() => unit.ReadClockAsync()).Should().ThrowAsync<NotSupportedException>();
        line.BytesSent.Should().Be(0);

        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = model });
        (await raw.TransactAsync(RawHost.Command("@00FA000000000010182000000000001"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task QQ_is_used_where_the_model_has_it_and_refused_before_the_wire_where_not(string model, bool fins, bool qq, bool mmXz)
    {
        _ = fins;
        _ = mmXz;
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        plc.WriteWord(PlcArea.Dm, 0, 0x0102);
        plc.WriteWord(PlcArea.Dm, 1, 0x0304);
        await using var line = EmulatedLine.Start(plc, model);

        if (qq)
        {
            (await line.Client.ReadCompoundAsync(["D0", "D1"])).Should().Equal((ushort)0x0102, (ushort)0x0304);
            line.SentFrames.Should().Contain(f => f.StartsWith("@00QQIR", StringComparison.Ordinal));
            return;
        }

        await FluentActions.Awaiting(() => line.Client.ReadCompoundAsync(["D0", "D1"])).Should().ThrowAsync<NotSupportedException>()
            .WithMessage($"*{PlcModelProfile.Parse(model).DisplayName} does not accept the C-mode compound read (QQ).");
        line.BytesSent.Should().Be(0);

        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = model });
        (await raw.TransactAsync(RawHost.Command("@00QQMRDM  0000CH"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task MM_and_XZ_are_refused_before_the_wire_on_a_model_whose_list_lacks_them(string model, bool fins, bool qq, bool mmXz)
    {
        _ = fins;
        _ = qq;
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = model });
        await using var line = EmulatedLine.Start(plc, model);

        if (mmXz)
        {
            await line.Client.AbortAsync();
            line.SentFrames.Should().ContainSingle().Which.Should().StartWith("@00XZ");
            return;
        }

        string name = PlcModelProfile.Parse(model).DisplayName;
        await FluentActions.Awaiting(() => line.Client.ReadModelAsync()).Should().ThrowAsync<NotSupportedException>()
            .WithMessage($"*{name} does not accept the C-mode PLC MODEL READ (MM).");
        await FluentActions.Awaiting(() => line.Client.AbortAsync()).Should().ThrowAsync<NotSupportedException>()
            .WithMessage($"*{name} does not accept the C-mode ABORT (XZ).");
        line.BytesSent.Should().Be(0);

        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = model });
        (await raw.TransactAsync(RawHost.Command("@00MM"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Fact]
    public async Task TS_and_the_status_commands_every_model_lists_go_through()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CP2E" });
        await using var line = EmulatedLine.Start(plc, "CP2E");

        await line.Client.TestAsync("ABC");
        (await line.Client.ReadStatusAsync()).Mode.Should().Be(PlcMode.Program);
        await line.Client.ReadErrorsAsync();
        await line.Client.SetModeAsync(PlcMode.Monitor);

        plc.Mode.Should().Be(PlcMode.Monitor);
    }
}
