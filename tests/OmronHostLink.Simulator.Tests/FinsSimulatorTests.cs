using System.Globalization;
using System.Text;
using OmronHostLink.Protocol.Fins;
using OmronHostLink.Simulator;

namespace OmronHostLink.Simulator.Tests;

/// <summary>FINS over Host Link (header FA) answered by the simulator.</summary>
public class FinsSimulatorTests
{
    private static readonly FinsHeader Direct = FinsHeader.Direct();

    public static TheoryData<string> FinsCommandVectors()
    {
        var data = new TheoryData<string>();
        foreach (SimVector v in SimVectors.Vectors)
        {
            if (v.Direction == "command" && v.FcsOk && v.Frames.Count == 1 && v.Frames[0].Length > 5 && v.Frames[0][3..5] == "FA")
            {
                data.Add(v.Name);
            }
        }

        return data;
    }

    private static string Frame(FinsCommand command, int unit = 0, FinsHeader? header = null)
        => Encoding.ASCII.GetString(FinsMessage.EncodeCommandFrame(unit, header ?? Direct, command));

    private static FinsResponse Parse(string frame, FinsCommand command, int unit = 0, FinsHeader? header = null)
        => FinsResponse.ParseFrame(Encoding.ASCII.GetBytes(frame), unit, header ?? Direct, command.CommandCode);

    private static async Task<FinsResponse> TransactAsync(RawHost host, FinsCommand command, FinsHeader? header = null)
        => Parse(await host.TransactAsync(Frame(command, 0, header)), command, 0, header);

    [Theory]
    [MemberData(nameof(FinsCommandVectors))]
    public async Task Every_FINS_command_vector_gets_a_well_formed_response(string name)
    {
        SimVector v = SimVectors.Get(name);
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { Units = Enumerable.Range(0, 32).ToArray() });
        byte[] command = Encoding.ASCII.GetBytes(v.Frames[0]);
        FinsCommandMessage sent = FinsMessage.ParseCommandFrame(command);
        string answer = await host.TransactAsync(v.Frames[0]);

        FinsResponse r = FinsResponse.ParseFrame(Encoding.ASCII.GetBytes(answer), sent.Unit, sent.Header, sent.CommandCode);
        r.Unit.Should().Be(sent.Unit);
        r.Header.Sid.Should().Be(sent.Header.Sid);
        r.Header.IsResponse.Should().BeTrue();
        r.Header.IsNetwork.Should().Be(sent.Header.IsNetwork);
        r.CommandCode.Should().Be(sent.CommandCode);
        r.EndCode.Raw.Should().Be(0x0000, $"{name}: {r.EndCode.Meaning}");
    }

    [Theory]
    [InlineData("f_0101_cmd", "f_0101_rsp")]
    [InlineData("cs_fins_read_h13", "cs_fins_read_h13_resp")]
    [InlineData("f_0102_cmd", "hsl_fins_write_resp")]
    [InlineData("f_0104_cmd", "f_0104_rsp")]
    [InlineData("f_0402_stop", "f_0402_rsp")]
    [InlineData("f_0601_cmd", "f_0601_rsp")]
    public async Task Responses_reproduce_the_vectors_byte_for_byte(string command, string response)
    {
        var plc = new VirtualPlc(new VirtualPlcOptions { InitialMode = PlcMode.Monitor });
        plc.WriteWords(PlcArea.Dm, 100, [0x1234, 0xABCD]);
        plc.WriteWords(PlcArea.Dm, 0, [0x1111]);
        plc.WriteWords(PlcArea.Cio, 1, [0x2222]);
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync(SimVectors.Get(command).Frames[0])).Should().Be(SimVectors.Get(response).Frames[0]);
    }

    [Fact]
    public async Task The_network_form_swaps_source_and_destination()
    {
        var plc = new VirtualPlc();
        plc.WriteWords(PlcArea.Dm, 0, [0xABCD]);
        await using RawHost host = RawHost.Start(plc);
        (await host.TransactAsync(SimVectors.Get("f_network_cmd").Frames[0])).Should().Be(SimVectors.Get("f_network_rsp").Frames[0]);
    }

    [Fact]
    public async Task Response_codes_carry_the_non_fatal_error_flag()
    {
        var plc = new VirtualPlc();
        plc.SetError(0, 1);
        await using RawHost host = RawHost.Start(plc);
        string frame = Frame(new MemoryAreaReadCommand(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0), 1));
        (await host.TransactAsync(frame)).Should().Be(SimVectors.Get("f_rsp_0040_nonfatal").Frames[0]);
    }

    [Fact]
    public async Task Out_of_range_and_read_only_addresses_are_refused()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(Frame(new MemoryAreaReadCommand(new FinsMemoryAddress(FinsMemoryArea.DmWord, 32767), 2))))
            .Should().Be(SimVectors.Get("f_rsp_1103").Frames[0]);
        (await host.TransactAsync(Frame(MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.AuxiliaryWord, 447), [1]))))
            .Should().Be(SimVectors.Get("f_0102_rsp_2101").Frames[0]);
        (await TransactAsync(host, MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.AuxiliaryWord, 448), [1]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, new MemoryAreaReadCommand(new FinsMemoryAddress(FinsMemoryArea.CioWordForced, 0), 1))).EndCode.Raw.Should().Be(0x1101);
        (await TransactAsync(host, new RawFinsCommand(0x0F0F, []))).EndCode.Raw.Should().Be(0x0401);
    }

    [Fact]
    public async Task A_damaged_FINS_part_gets_a_Host_Link_format_error()
    {
        await using RawHost host = RawHost.Start();
        (await host.TransactAsync(RawHost.Command("@00FA00000000001018"))).Should().Be(SimVectors.Get("f_hl_err_14").Frames[0], "an odd number of hex characters");
        (await host.TransactAsync(RawHost.Command("@00FA000000000010182"))).Should().Be(RawHost.Command("@00FA00400000000101" + "1002"), "a readable but short command is a FINS-level error");
        (await host.TransactAsync(RawHost.Command("@00FAX"))).Should().Be(SimVectors.Get("f_hl_err_14").Frames[0]);
    }

    [Fact]
    public async Task FINS_writes_work_in_RUN_mode_and_reach_every_area()
    {
        await using RawHost host = RawHost.Start(new VirtualPlcOptions { InitialMode = PlcMode.Run });
        (await TransactAsync(host, MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.DmWord, 20000), [7, 8]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.WorkWord, 3), [9]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, MemoryAreaWriteCommand.Words(new FinsMemoryAddress((byte)(FinsMemoryArea.EmBank0Word + 3), 30000), [10]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.TimerCounterPv, FinsMemoryArea.CounterAddress(4000)), [11]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, MemoryAreaWriteCommand.Bits(new FinsMemoryAddress(FinsMemoryArea.CioBit, 5, 15), [true, true]))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, MemoryAreaWriteCommand.Bits(new FinsMemoryAddress(FinsMemoryArea.TimerCounterFlag, 2), [true]))).EndCode.Raw.Should().Be(0);

        host.Plc.ReadWords(PlcArea.Dm, 20000, 2).Should().Equal(7, 8);
        host.Plc.ReadWord(PlcArea.Work, 3).Should().Be(9);
        host.Plc.ReadWord(PlcArea.Em, 30000, bank: 3).Should().Be(10);
        host.Plc.ReadWord(PlcArea.Counter, 4000).Should().Be(11);
        host.Plc.ReadWords(PlcArea.Cio, 5, 2).Should().Equal(0x8000, 0x0001);
        host.Plc.GetFlag(PlcArea.Timer, 2).Should().BeTrue();

        FinsResponse bits = await TransactAsync(host, new MemoryAreaReadCommand(new FinsMemoryAddress(FinsMemoryArea.CioBit, 5, 14), 4));
        bits.Data.ToArray().Should().Equal(0, 1, 1, 0);
    }

    [Fact]
    public async Task Fill_and_transfer_change_memory()
    {
        await using RawHost host = RawHost.Start();
        (await TransactAsync(host, new MemoryAreaFillCommand(new FinsMemoryAddress(FinsMemoryArea.DmWord, 10), 5, 0x5A5A))).EndCode.Raw.Should().Be(0);
        (await TransactAsync(host, new MemoryAreaTransferCommand(new FinsMemoryAddress(FinsMemoryArea.DmWord, 10), new FinsMemoryAddress(FinsMemoryArea.HoldingWord, 0), 5))).EndCode.Raw.Should().Be(0);
        host.Plc.ReadWords(PlcArea.Holding, 0, 6).Should().Equal(0x5A5A, 0x5A5A, 0x5A5A, 0x5A5A, 0x5A5A, 0);
    }

    [Fact]
    public async Task Run_stop_and_status_follow_the_mode()
    {
        var plc = new VirtualPlc { FalMessage = "HELLO" };
        await using RawHost host = RawHost.Start(plc);
        (await TransactAsync(host, new RunCommand(FinsCpuMode.Run))).EndCode.Raw.Should().Be(0);
        plc.Mode.Should().Be(PlcMode.Run);
        FinsCpuStatus status = FinsCpuStatus.Read((await TransactAsync(host, FinsCommands.CpuUnitStatusReadCommand)).Data.Span);
        status.Mode.Should().Be(FinsCpuMode.Run);
        status.IsRunning.Should().BeTrue();
        status.ErrorMessage.Should().Be("HELLO");
        (await host.TransactAsync(RawHost.Command("@00MS"))).Should().StartWith("@00MS0002B0");

        (await TransactAsync(host, new RunCommand(FinsCpuMode.Monitor))).EndCode.Raw.Should().Be(0);
        plc.Mode.Should().Be(PlcMode.Monitor);
        (await TransactAsync(host, new StopCommand())).EndCode.Raw.Should().Be(0);
        plc.Mode.Should().Be(PlcMode.Program);
    }

    [Fact]
    public async Task Unit_data_clock_cycle_time_and_error_log_are_answered()
    {
        var plc = new VirtualPlc();
        plc.SetError(0x8000, 0);
        await using RawHost host = RawHost.Start(plc);

        FinsResponse data = await TransactAsync(host, new CpuUnitDataReadCommand());
        FinsCpuUnitData.Read(data.Data.Span).Model.Should().Be("CJ1M-CPU13");
        data.EndCode.FatalCpuError.Should().BeTrue();

        var when = new DateTime(2024, 5, 17, 13, 45, 30);
        (await TransactAsync(host, new ClockWriteCommand(when))).EndCode.Code.Should().Be(0);
        FinsClock clock = FinsClock.Read((await TransactAsync(host, FinsCommands.ClockReadCommand)).Data.Span);
        clock.Time.Should().BeCloseTo(when, TimeSpan.FromSeconds(2));

        FinsCycleTime.Read((await TransactAsync(host, new CycleTimeReadCommand())).Data.Span).Average.Should().Be(TimeSpan.FromMilliseconds(1));
        FinsErrorLog.Read((await TransactAsync(host, new ErrorLogReadCommand(0, 5))).Data.Span).StoredRecords.Should().Be(0);

        (await TransactAsync(host, new ErrorClearCommand())).EndCode.Raw.Should().Be(0);
        plc.Errors.HasErrors.Should().BeFalse();
    }

    [Fact]
    public async Task Forced_set_and_reset_reach_C_mode_reads()
    {
        await using RawHost host = RawHost.Start();
        (await TransactAsync(host, new ForcedSetResetCommand(FinsForceAction.ForceSet, new FinsMemoryAddress(FinsMemoryArea.CioBit, 1, 3)))).EndCode.Raw.Should().Be(0);
        host.Plc.WriteWord(PlcArea.Cio, 1, 0);
        (await host.TransactAsync(RawHost.Command("@00RR00010001"))).Should().Be(RawHost.Command("@00RR000008"));
        (await TransactAsync(host, FinsCommands.ForcedCancelCommand)).EndCode.Raw.Should().Be(0);
        host.Plc.HasForcedBits.Should().BeFalse();

        host.Plc.Mode = PlcMode.Run;
        (await TransactAsync(host, new ForcedSetResetCommand(FinsForceAction.ForceSet, new FinsMemoryAddress(FinsMemoryArea.CioBit, 1, 3)))).EndCode.Raw.Should().Be(0x2206);
    }

    [Fact]
    public async Task Long_FA_frames_are_never_divided()
    {
        var plc = new VirtualPlc();
        ushort[] words = Enumerable.Range(0, MemoryAreaReadCommand.MaxWords).Select(i => (ushort)(i * 3)).ToArray();
        await using RawHost host = RawHost.Start(plc);
        string write = Frame(MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0), words.AsSpan(0, 200)));
        write.Length.Should().BeGreaterThan(131);
        Parse(await host.TransactAsync(write), MemoryAreaWriteCommand.Words(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0), words.AsSpan(0, 200))).EndCode.Raw.Should().Be(0);
        plc.WriteWords(PlcArea.Dm, 0, words);

        var read = new MemoryAreaReadCommand(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0), MemoryAreaReadCommand.MaxWords);
        string answer = await host.TransactAsync(Frame(read));
        answer.Length.Should().BeLessThanOrEqualTo(FinsMessage.MaxFrameLength).And.BeGreaterThan(1000);
        FinsWords.Read(Parse(answer, read).Data.Span, words.Length).Should().Equal(words);
    }

    [Fact]
    public async Task The_response_wait_time_delays_the_answer()
    {
        await using RawHost host = RawHost.Start();
        FinsHeader header = FinsHeader.Direct(sid: 0x2A, responseWait: 10);
        var clock = System.Diagnostics.Stopwatch.StartNew();
        FinsResponse r = await TransactAsync(host, FinsCommands.CpuUnitStatusReadCommand, header);
        clock.Elapsed.Should().BeGreaterThanOrEqualTo(TimeSpan.FromMilliseconds(95));
        r.Header.Sid.Should().Be(0x2A);
    }

    [Fact]
    public void The_FINS_command_vectors_are_there()
    {
        ((IEnumerable<object[]>)FinsCommandVectors()).Count().Should().BeGreaterThan(15);
        _ = CultureInfo.InvariantCulture;
    }
}
