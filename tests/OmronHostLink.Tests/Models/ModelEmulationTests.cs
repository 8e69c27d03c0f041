using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// The simulator emulating a model and the client checked against it: commands the model lacks answered IC, the memory
/// its manual says reads 0000, MM detection, refusals in the user's words. The edges of every profile's memory are
/// <see cref="ModelEdgeTableTests"/>; its commands, <see cref="ModelCommandTableTests"/>.
/// </summary>
public sealed class ModelEmulationTests
{
    [Theory]
    [InlineData("CP2E", "QQ")]
    [InlineData("CP2E", "RL")]
    [InlineData("CP1E-E", "RE")]
    [InlineData("CP1E-E", "QQ")]
    [InlineData("C200HS", "RE")]
    public async Task The_simulator_answers_a_command_the_model_lacks_with_IC(string model, string header)
    {
        await using RawHost raw = RawHost.Start(new VirtualPlcOptions { Model = model });

        (await raw.TransactAsync(RawHost.Command("@00" + header + "00000001"))).Should().Be(RawHost.Command("@00IC"));
    }

    [Fact]
    public async Task A_C200HS_simulator_answers_DM_it_does_not_have_with_0000_and_refuses_what_RD_cannot_name()
    {
        // C200HS Operation Manual p409, RD note 2: DM 6656–6999 do not exist; reading them returns 0000, no error.
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "C200HS" });
        plc.WriteWord(PlcArea.Dm, 6655, 0x1234);
        plc.WriteWord(PlcArea.Dm, 6656, 0x5678);
        await using RawHost raw = RawHost.Start(plc);

        (await raw.TransactAsync(RawHost.Command("@00RD66550002"))).Should().Be(RawHost.Command("@00RD0012340000"));
        (await raw.TransactAsync(RawHost.Command("@00MM"))).Should().Be(RawHost.Command("@00MM0012"));
        (await raw.TransactAsync(RawHost.Command("@00RC05120001"))).Should().Be(RawHost.Command("@00RC15"));
    }

    [Fact]
    public async Task A_client_with_model_auto_refuses_the_read_a_C200HS_would_answer_with_0000()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "C200HS" });
        plc.WriteWord(PlcArea.Dm, 6656, 0x5678);

        // Without a model the read goes out and the PLC's 0000 comes back as if it were a value: the hazard.
        await using (var unchecked_ = EmulatedLine.Start(plc, null))
        {
            (await unchecked_.Client.ReadWordsAsync("D6656", 1)).Should().Equal((ushort)0);
        }

        await using var line = EmulatedLine.Start(plc, "auto");
        await line.Client.ReadWordsAsync("D100", 1); // first use: MM
        long sent = line.BytesSent;

        var e = await FluentActions.Awaiting(() => line.Client.ReadWordsAsync("D6656", 1)).Should().ThrowAsync<ArgumentOutOfRangeException>();

        e.Which.Message.Should().StartWith("D6656 is beyond the DM area of a PLC answering MM 12 (C200H, C200HS, C200HX/HG/HE");
        line.BytesSent.Should().Be(sent);
    }

    [Fact]
    public async Task A_configured_model_refuses_before_the_wire_in_the_users_words()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CP1E-E" });
        await using var line = EmulatedLine.Start(plc, "CP1E-E");

        var e = await FluentActions.Awaiting(() => line.Client.ReadWordsAsync("D2048", 1)).Should().ThrowAsync<ArgumentOutOfRangeException>();

        e.Which.Message.Should().StartWith("D2048 is beyond the DM area of a CP1E E-type (D0–D2047).");
        line.BytesSent.Should().Be(0);
    }

    [Fact]
    public async Task Counters_of_a_shared_TC_space_are_read_with_RC_at_their_own_number()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc.WriteWord(PlcArea.Counter, 5, 0x0042);
        await using RawHost raw = RawHost.Start(plc);
        (await raw.TransactAsync(RawHost.Command("@00RC00050001"))).Should().Be(RawHost.Command("@00RC000042"));

        var plc2 = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        plc2.WriteWord(PlcArea.Timer, 5, 0x0042);
        await using var line = EmulatedLine.Start(plc2, "CPM1A");
        (await line.Client.ReadWordsAsync("C5", 1)).Should().Equal((ushort)0x0042);
        (await line.Client.ReadWordsAsync("TC5", 1)).Should().Equal((ushort)0x0042);
    }

    [Fact]
    public async Task QQ_is_refused_before_the_wire_on_a_model_without_it_and_answered_on_one_with_it()
    {
        var cp2e = new VirtualPlc(new VirtualPlcOptions { Model = "CP2E" });
        await using (var line = EmulatedLine.Start(cp2e, "CP2E"))
        {
            await FluentActions.Awaiting(() => line.Client.ReadCompoundAsync(["D0", "D1"])).Should().ThrowAsync<NotSupportedException>()
                .WithMessage("A CP2E does not accept the C-mode compound read (QQ).");
            line.BytesSent.Should().Be(0);
        }

        var cpm1a = new VirtualPlc(new VirtualPlcOptions { Model = "CPM1A" });
        cpm1a.WriteWord(PlcArea.Dm, 6144, 0x0102);
        await using (var line = EmulatedLine.Start(cpm1a, "CPM1A"))
        {
            await FluentActions.Awaiting(() => line.Client.ReadCompoundAsync(["D0", "D2000"])).Should().ThrowAsync<ArgumentOutOfRangeException>()
                .WithMessage("D2000 is beyond the DM area of a CPM1/CPM1A*");
            line.BytesSent.Should().Be(0);
        }
    }

    [Fact]
    public void An_unknown_model_is_refused_when_the_options_are_checked()
    {
        var options = new HostLinkClientOptions { Model = "CPM9" };
        FluentActions.Invoking(options.Validate).Should().Throw<ArgumentException>()
            .WithMessage("Model 'CPM9' is not a known PLC model; use one of C200H, *, or auto to ask the PLC (MM).*");
        FluentActions.Invoking(() => new VirtualPlc(new VirtualPlcOptions { Model = "CPM9" })).Should().Throw<ArgumentException>();
    }
}
