using OmronHostLink.Simulator;

namespace OmronHostLink.Simulator.Tests;

/// <summary>C-mode command behaviour of the simulator, driven with raw frames.</summary>
public class SimulatorCommandTests
{
    private static string Cmd(string message) => RawHost.Command(message);

    [Fact]
    public async Task Reads_return_memory_of_each_area()
    {
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Cio, 10, [0x1234, 0xABCD]);
        plc.WriteWords(PlcArea.Cio, 1005, [0x0105]);
        plc.WriteWords(PlcArea.Holding, 500, [0x0500]);
        plc.WriteWords(PlcArea.Dm, 9999, [0xBEEF]);
        plc.WriteWords(PlcArea.Auxiliary, 959, [0x0959]);
        plc.WriteWords(PlcArea.Timer, 5, [0x0123]);
        plc.WriteWords(PlcArea.Counter, 0, [0x0456]);
        plc.WriteWords(PlcArea.Em, 100, [0x0E0C], bank: 0xC);
        await using RawHost host = RawHost.Start(plc);

        (await host.TransactAsync(Cmd("@00RR00100002"))).Should().Be(Cmd("@00RR001234ABCD"));
        (await host.TransactAsync(Cmd("@00RL00050001"))).Should().Be(Cmd("@00RL000105"), "LR 5 is CIO 1005");
        (await host.TransactAsync(Cmd("@00RH05000001"))).Should().Be(Cmd("@00RH000500"));
        (await host.TransactAsync(Cmd("@00RD99990001"))).Should().Be(Cmd("@00RD00BEEF"));
        (await host.TransactAsync(Cmd("@00RJ09590001"))).Should().Be(Cmd("@00RJ000959"));
        (await host.TransactAsync(Cmd("@00RC00050001"))).Should().Be(Cmd("@00RC000123"));
        (await host.TransactAsync(Cmd("@00RC20480001"))).Should().Be(Cmd("@00RC000456"), "C-mode 2048 is counter 0");
        (await host.TransactAsync(Cmd("@00RE0C01000001"))).Should().Be(Cmd("@00RE000E0C"));
    }

    [Fact]
    public async Task RG_reports_completion_flags_one_character_each()
    {
        var plc = new VirtualPlc();
        plc.SetFlag(PlcArea.Timer, 1, true);
        plc.SetFlag(PlcArea.Counter, 0, true);
        plc.SetFlag(PlcArea.Counter, 2, true);
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync(Cmd("@00RG00000003"))).Should().Be(Cmd("@00RG00010"));
        (await host.TransactAsync(Cmd("@00RG20480004"))).Should().Be(Cmd("@00RG001010"));
    }

    [Fact]
    public async Task Writes_change_memory_of_each_area()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00WR00200001FFFF"))).Should().Be(Cmd("@00WR00"));
        (await host.TransactAsync(Cmd("@00WL01991111"))).Should().Be(Cmd("@00WL00"));
        (await host.TransactAsync(Cmd("@00WH00102222"))).Should().Be(Cmd("@00WH00"));
        (await host.TransactAsync(Cmd("@00WD00003333"))).Should().Be(Cmd("@00WD00"));
        (await host.TransactAsync(Cmd("@00WJ04484444"))).Should().Be(Cmd("@00WJ00"));
        (await host.TransactAsync(Cmd("@00WC20490555"))).Should().Be(Cmd("@00WC00"));
        (await host.TransactAsync(Cmd("@00WE0299996666"))).Should().Be(Cmd("@00WE00"));

        host.Plc.ReadWords(PlcArea.Cio, 20, 2).Should().Equal(0x0001, 0xFFFF);
        host.Plc.ReadWord(PlcArea.Cio, 1199).Should().Be(0x1111);
        host.Plc.ReadWord(PlcArea.Holding, 10).Should().Be(0x2222);
        host.Plc.ReadWord(PlcArea.Dm, 0).Should().Be(0x3333);
        host.Plc.ReadWord(PlcArea.Auxiliary, 448).Should().Be(0x4444);
        host.Plc.ReadWord(PlcArea.Counter, 1).Should().Be(0x0555);
        host.Plc.ReadWord(PlcArea.Em, 9999, bank: 2).Should().Be(0x6666);
        host.Plc.ReadWords("E2_9999", 1).Should().Equal(0x6666);
    }

    [Fact]
    public async Task Writes_in_RUN_mode_are_refused_with_01_and_allowed_in_MONITOR()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { InitialMode = PlcMode.Run });
        (await host.TransactAsync(Cmd("@00WD01000001"))).Should().Be(Response.Error(0, "WD", "01"));
        (await host.TransactAsync(Cmd("@00KSCIO 000101"))).Should().Be(Response.Error(0, "KS", "01"));
        host.Plc.ReadWord(PlcArea.Dm, 100).Should().Be(0);

        (await host.TransactAsync(Cmd("@00RD01000001"))).Should().Be(Cmd("@00RD000000"), "reads work in RUN");
        (await host.TransactAsync(Cmd("@00SC02"))).Should().Be(Cmd("@00SC00"));
        host.Plc.Mode.Should().Be(PlcMode.Monitor);
        (await host.TransactAsync(Cmd("@00WD01000001"))).Should().Be(Cmd("@00WD00"));
        host.Plc.ReadWord(PlcArea.Dm, 100).Should().Be(1);
    }

    [Fact]
    public async Task A_multi_frame_write_in_RUN_mode_is_refused_after_the_last_frame()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { InitialMode = PlcMode.Run });
        SimVector v = SimVectors.Get("c_wd_multi_command_50w");
        (await host.TransactAsync(v.Frames[0])).Should().Be("\r");
        (await host.TransactAsync(v.Frames[1])).Should().Be(Response.Error(0, "WD", "01"));
        host.Plc.ReadWord(PlcArea.Dm, 1000).Should().Be(0);
    }

    [Theory]
    [InlineData(PlcMode.Program, "00B0")]
    [InlineData(PlcMode.Run, "02B0")]
    [InlineData(PlcMode.Monitor, "03B0")]
    public async Task MS_reports_the_mode_in_status_bits_9_and_8(PlcMode mode, string status)
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { InitialMode = mode });
        (await host.TransactAsync(Cmd("@00MS"))).Should().Be(Cmd("@00MS00" + status));
    }

    [Fact]
    public async Task MS_adds_the_FAL_message_padded_to_16_characters()
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { InitialMode = PlcMode.Run }) { FalMessage = "FAL MESSAGE 01" };
        await using RawHost host = RawHost.Start(plc);
        // The vector's status low byte is 00, which names no program area; a CS/CJ with writable UM and a 30K-step
        // program area sends B0 there (W342 4-3-23). Everything else is the vector's.
        string vector = SimVectors.Get("c_ms_resp_run_msg").Frames[0];
        (await host.TransactAsync(Cmd("@00MS"))).Should().Be(Cmd(vector[..9] + "B0" + vector[11..^4]));
    }

    [Fact]
    public async Task SC_changes_the_mode_with_its_own_coding()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00SC03"))).Should().Be(Cmd("@00SC00"));
        host.Plc.Mode.Should().Be(PlcMode.Run);
        (await host.TransactAsync(Cmd("@00SC02"))).Should().Be(Cmd("@00SC00"));
        host.Plc.Mode.Should().Be(PlcMode.Monitor);
        (await host.TransactAsync(Cmd("@00SC00"))).Should().Be(SimVectors.Get("roof_sc_resp_ok").Frames[0]);
        host.Plc.Mode.Should().Be(PlcMode.Program);
        (await host.TransactAsync(Cmd("@00SC01"))).Should().Be(Response.Error(0, "SC", "15"));
    }

    [Fact]
    public async Task MF_reports_the_error_words_and_clears_them_on_request()
    {
        var plc = new VirtualPlc();
        plc.SetError(0x8000, 0x0042);
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync(Cmd("@00MF00"))).Should().Be(Cmd("@00MF0080000042"));
        (await host.TransactAsync(Cmd("@00MF01"))).Should().Be(Cmd("@00MF0080000042"));
        (await host.TransactAsync(Cmd("@00MF00"))).Should().Be(SimVectors.Get("c_mf_resp").Frames[0]);
        plc.Errors.HasErrors.Should().BeFalse();
    }

    [Fact]
    public async Task MM_reports_the_model_code()
    {
        await using (RawHost host = RawHost.Start())
        {
            (await host.TransactAsync(Cmd("@00MM"))).Should().Be(SimVectors.Get("c_mm_resp_csj").Frames[0]);
        }

        await using (RawHost host = RawHost.Start(new VirtualPlcOptions { ModelCode = 0x12 }))
        {
            (await host.TransactAsync(Cmd("@00MM"))).Should().Be(Cmd("@00MM0012"));
        }
    }

    [Fact]
    public async Task TS_echoes_its_text_without_an_end_code()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00TSHELLO-PLC"))).Should().Be(SimVectors.Get("c_ts_resp").Frames[0]);
        string longest = new('x', 122);
        (await host.TransactAsync(Cmd("@00TS" + longest))).Should().Be(Cmd("@00TS" + longest));
    }

    [Fact]
    public async Task Forced_bits_are_applied_to_reads_and_survive_writes_until_cancelled()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00KSCIO 000103"))).Should().Be(Cmd("@00KS00"));
        (await host.TransactAsync(Cmd("@00KRHR  000500"))).Should().Be(Cmd("@00KR00"));
        host.Plc.WriteWord(PlcArea.Holding, 5, 0xFFFF);
        (await host.TransactAsync(Cmd("@00WR00010000"))).Should().Be(Cmd("@00WR00"));
        (await host.TransactAsync(Cmd("@00RR00010001"))).Should().Be(Cmd("@00RR000008"));
        (await host.TransactAsync(Cmd("@00RH00050001"))).Should().Be(Cmd("@00RH00FFFE"));
        host.Plc.GetForced(PlcArea.Cio, 1, 3).Should().BeTrue();
        host.Plc.GetForced(PlcArea.Holding, 5, 0).Should().BeFalse();

        (await host.TransactAsync(Cmd("@00KC"))).Should().Be(SimVectors.Get("c_kc_resp").Frames[0]);
        host.Plc.HasForcedBits.Should().BeFalse();
        (await host.TransactAsync(Cmd("@00WR00010000"))).Should().Be(Cmd("@00WR00"));
        (await host.TransactAsync(Cmd("@00RR00010001"))).Should().Be(Cmd("@00RR000000"));
    }

    [Fact]
    public async Task KS_and_KR_force_timer_and_counter_flags()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00KSTIM 001000"))).Should().Be(Cmd("@00KS00"));
        (await host.TransactAsync(Cmd("@00KSCNT 000200"))).Should().Be(Cmd("@00KS00"));
        host.Plc.SetFlag(PlcArea.Timer, 10, false);
        host.Plc.GetFlag(PlcArea.Timer, 10).Should().BeTrue();
        (await host.TransactAsync(Cmd("@00RG00100001"))).Should().Be(Cmd("@00RG001"));
        (await host.TransactAsync(Cmd("@00RG20500001"))).Should().Be(Cmd("@00RG001"));
        (await host.TransactAsync(SimVectors.Get("c_kr_tim").Frames[0])).Should().Be(Cmd("@00KR00"));
        host.Plc.GetFlag(PlcArea.Timer, 10).Should().BeFalse();
    }

    [Fact]
    public async Task FK_sets_resets_forces_and_cancels_bits_of_one_word()
    {
        var plc = new VirtualPlc();
        plc.ForceBit(PlcArea.Cio, 10, 0, true);
        await using RawHost host = RawHost.Start(plc);

        // bit15 set, bit14 reset, bit13 forced set, bit12 forced reset, ..., bit0 cancel.
        (await host.TransactAsync(Cmd("@00FKCIO 00103254000000000008"))).Should().Be(Cmd("@00FK00"));
        plc.ReadWord(PlcArea.Cio, 10).Should().Be(0xA001, "the cancelled bit 0 keeps the state it was forced to");
        plc.GetForced(PlcArea.Cio, 10, 13).Should().BeTrue();
        plc.GetForced(PlcArea.Cio, 10, 12).Should().BeFalse();
        plc.GetForced(PlcArea.Cio, 10, 15).Should().BeNull();
        plc.GetForced(PlcArea.Cio, 10, 0).Should().BeNull();
        plc.WriteWord(PlcArea.Cio, 10, 0x1000);
        plc.ReadWord(PlcArea.Cio, 10).Should().Be(0x2000);
    }

    [Theory]
    [InlineData("@00RD99990002")] // past the C-mode DM range
    [InlineData("@00RD00000000")] // count 0
    [InlineData("@00RDA0000001")] // not BCD
    [InlineData("@00RR61440001")]
    [InlineData("@00RH05110002")]
    [InlineData("@00RC40960001")]
    [InlineData("@00RE0D00000001")] // bank D
    [InlineData("@00RJ09600001")]
    [InlineData("@00WD9999000A000B")]
    [InlineData("@00WD0000XYZW")]
    public async Task Out_of_range_or_invalid_entries_are_answered_with_15(string message)
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd(message))).Should().Be(Response.Error(0, message.Substring(3, 2), "15"));
    }

    [Theory]
    [InlineData(0)]
    [InlineData(447)]
    public async Task The_read_only_auxiliary_words_cannot_be_written(int word)
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { InitialMode = PlcMode.Monitor });
        (await host.TransactAsync(Cmd($"@00WJ{word:D4}1234"))).Should().Be(Response.Error(0, "WJ", "15"));
        host.Plc.ReadWord(PlcArea.Auxiliary, word).Should().Be(0);
        (await host.TransactAsync(Cmd("@00WJ04471234ABCD"))).Should().Be(Response.Error(0, "WJ", "15"));
        host.Plc.ReadWord(PlcArea.Auxiliary, 448).Should().Be(0);
    }

    [Theory]
    [InlineData("@00RD000000")]       // too short
    [InlineData("@00RD0000000100")]   // too long
    [InlineData("@00WD0000123")]      // not whole words
    [InlineData("@00WD0000")]         // no data
    [InlineData("@00MS00")]
    [InlineData("@00MF0")]
    public async Task Wrong_lengths_are_answered_with_14(string message)
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd(message))).Should().Be(Response.Error(0, message.Substring(3, 2), "14"));
    }

    [Fact]
    public async Task A_frame_with_a_bad_FCS_is_answered_with_13_and_the_header()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync("@00RD0000000100*\r")).Should().Be(SimVectors.Get("c_rd_err_13").Frames[0]);
    }

    [Fact]
    public async Task A_first_frame_over_131_characters_is_answered_with_18()
    {
        await using RawHost host = RawHost.Start();
        string frame = Cmd("@00TS" + new string('x', 123));
        frame.Length.Should().Be(132);
        (await host.TransactAsync(frame)).Should().Be(Response.Error(0, "TS", "18"));
        (await host.TransactAsync(Cmd("@00WD0000" + string.Concat(Enumerable.Repeat("0001", 30))))).Should().Be(Response.Error(0, "WD", "18"));
    }

    [Fact]
    public async Task An_unknown_header_is_answered_with_IC()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00ZZ"))).Should().Be(SimVectors.Get("c_ic_resp").Frames[0]);
        (await host.TransactAsync(Cmd("@00RP"))).Should().Be(SimVectors.Get("c_ic_resp").Frames[0]);
    }

    [Fact]
    public async Task QQ_is_executed_a_registration_without_items_is_a_format_error()
    {
        // W342 4-3-35: QQMR end code 14 for a missing item; the answer echoes the sub-header before the end code.
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00QQMR"))).Should().Be("@00QQMR145A*\r");
    }

    [Fact]
    public async Task XZ_and_initialize_get_no_answer()
    {
        await using RawHost host = RawHost.Start();
        await host.SendAsync(Cmd("@00XZ"));
        await host.ExpectSilenceAsync();
        await host.SendAsync("@**\r");
        await host.ExpectSilenceAsync();
        (await host.TransactAsync(Cmd("@00MS"))).Should().StartWith("@00MS00");
    }

    [Fact]
    public async Task A_non_divisible_command_sent_as_a_first_of_several_frames_is_answered_with_14()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(RawHost.Delimited("@00RD00000001"))).Should().Be(Response.Error(0, "RD", "14"));
        (await host.TransactAsync(RawHost.Delimited("@00ZZ"))).Should().Be(SimVectors.Get("c_ic_resp").Frames[0]);
    }

    [Fact]
    public async Task A_divided_write_must_carry_the_first_word_in_its_first_frame()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(RawHost.Delimited("@00WD0000"))).Should().Be(Response.Error(0, "WD", "14"));
        (await host.TransactAsync(RawHost.Delimited("@00WD00001G34"))).Should().Be(Response.Error(0, "WD", "15"));
    }

    [Theory]
    [InlineData("0001000200*\r", "A3")] // wrong FCS (00; the text gives 03)
    [InlineData("0001000X", "A5")]       // non-hex data in a later frame
    [InlineData("000100", "A4")]         // not whole words
    [InlineData("00", "A3")]             // two characters or fewer
    public async Task Errors_in_later_command_frames_abort_with_A_codes(string continuation, string code)
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(RawHost.Delimited("@00WD00000001"))).Should().Be("\r");
        string frame = continuation.EndsWith('\r') ? continuation : RawHost.Command(continuation);
        (await host.TransactAsync(frame)).Should().Be(Response.Error(0, "WD", code));
        host.Plc.ReadWord(PlcArea.Dm, 0).Should().Be(0, "an aborted write changes nothing");
        (await host.TransactAsync(Cmd("@00MS"))).Should().StartWith("@00MS00", "the line is idle again");
    }

    [Fact]
    public async Task A_later_command_frame_over_128_characters_aborts_with_A8()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(RawHost.Delimited("@00WD00000001"))).Should().Be("\r");
        string later = RawHost.Command(string.Concat(Enumerable.Repeat("0002", 32)));
        later.Length.Should().Be(132);
        (await host.TransactAsync(later)).Should().Be(Response.Error(0, "WD", "A8"));
    }

    [Fact]
    public async Task A_multi_frame_answer_is_abandoned_by_XZ_or_initialize()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00RD00000070"))).Should().StartWith("@00RD00");
        await host.SendAsync(Cmd("@00XZ"));
        await host.ExpectSilenceAsync();
        (await host.TransactAsync(Cmd("@00MS"))).Should().Be(Cmd("@00MS0000B0"));

        (await host.TransactAsync(Cmd("@00RD00000070"))).Should().StartWith("@00RD00");
        await host.SendAsync("@**\r");
        await host.ExpectSilenceAsync();
        (await host.TransactAsync(Cmd("@00MS"))).Should().Be(Cmd("@00MS0000B0"));
    }

    [Fact]
    public async Task Any_other_command_during_a_multi_frame_answer_counts_as_a_delimiter()
    {
        SimVector v = SimVectors.Get("c_rd_multi_response_70w");
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Dm, 0, Enumerable.Range(0, 70).Select(i => (ushort)(0xA000 + i)).ToArray());
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync(Cmd("@00RD00000070"))).Should().Be(v.Frames[0]);
        (await host.TransactAsync(Cmd("@00MS"))).Should().Be(v.Frames[1]);
        (await host.TransactAsync("\r")).Should().Be(v.Frames[2]);
    }

    [Fact]
    public async Task RG_answers_are_cut_at_121_and_124_points()
    {
        await using RawHost host = RawHost.Start();
        string first = await host.TransactAsync(Cmd("@00RG00000300"));
        first.Length.Should().Be(7 + 121 + 3);
        string second = await host.TransactAsync("\r");
        second.Length.Should().Be(124 + 3);
        string third = await host.TransactAsync("\r");
        third.Should().Be(RawHost.Command(new string('0', 300 - 121 - 124)));
    }

    [Fact]
    public async Task Garbage_on_the_line_is_skipped()
    {
        await using RawHost host = RawHost.Start();
        await host.SendAsync(new byte[] { 0x00, 0xFF, (byte)'x', (byte)'*', 0x13 });
        await host.SendAsync("junk without a frame\r");
        (await host.TransactAsync("zz\x01" + Cmd("@00MS"))).Should().Be(Cmd("@00MS0000B0"));
        await host.SendAsync(new string('z', 1500));
        (await host.TransactAsync("\r" + Cmd("@00MM"))).Should().Be(Cmd("@00MM0030"));
    }

    [Fact]
    public async Task Frames_arriving_byte_by_byte_are_assembled()
    {
        await using RawHost host = RawHost.Start();
        foreach (char c in Cmd("@00RD00000002"))
        {
            await host.SendAsync(c.ToString());
        }

        (await host.ReadFrameAsync()).Should().Be(Cmd("@00RD0000000000"));
    }

    [Fact]
    public async Task A_multidrop_PLC_answers_only_its_own_units()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Units = [1, 3] });
        (await host.TransactAsync(Cmd("@01MS"))).Should().StartWith("@01MS00");
        (await host.TransactAsync(Cmd("@03MS"))).Should().StartWith("@03MS00");
        foreach (string other in new[] { Cmd("@00MS"), Cmd("@02RD00000001"), "@02RD0000000100*\r", Cmd("@31ZZ") })
        {
            await host.SendAsync(other);
        }

        await host.ExpectSilenceAsync();
    }

    [Fact]
    public async Task Another_units_multi_frame_exchange_does_not_confuse_the_PLC()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Units = [1] });
        SimVector w = SimVectors.Get("c_wr_multi_command_80w");
        foreach (string frame in w.Frames)
        {
            await host.SendAsync(frame); // unit 00's frames
        }

        await host.SendAsync("\r"); // a delimiter another unit's answer would get
        await host.ExpectSilenceAsync();
        host.Plc.ReadWord(PlcArea.Cio, 0).Should().Be(0);
        (await host.TransactAsync(Cmd("@01RR00000001"))).Should().Be(Cmd("@01RR000000"));
    }

    [Fact]
    public async Task The_session_ends_when_the_stream_ends()
    {
        RawHost host = RawHost.Start();
        (await host.TransactAsync(Cmd("@00MS"))).Should().StartWith("@00MS");
        await host.CloseAsync();
        host.Session.IsCompletedSuccessfully.Should().BeTrue();
        await host.DisposeAsync();
    }

    [Fact]
    public async Task One_PLC_serves_several_sessions_in_turn()
    {
        var plc = new VirtualPlc();
        await using (RawHost first = RawHost.Start(plc))
        {
            (await first.TransactAsync(Cmd("@00WD00071234"))).Should().Be(Cmd("@00WD00"));
        }

        await using RawHost second = RawHost.Start(plc);
        (await second.TransactAsync(Cmd("@00RD00070001"))).Should().Be(Cmd("@00RD001234"));
    }
}
