using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

public class FinsCommandVectorTests
{
    public static IEnumerable<object[]> GoodCommands => FinsVectors.GoodCommands;

    [Theory]
    [MemberData(nameof(GoodCommands))]
    public void Command_vector_parses_to_a_typed_command_and_re_encodes_byte_for_byte(string name)
    {
        Vector vector = GoldenVectors.Get(name);
        byte[] frame = vector.FrameBytes();

        FrameInfo info = FrameParser.ParseFirst(frame);
        info.IsFinal.Should().BeTrue();
        FinsCommandMessage message = FinsMessage.ParseCommandFrame(frame);
        FinsCommand command = message.ToCommand();

        command.Should().NotBeOfType<RawFinsCommand>("every FINS command vector uses a command this library models");
        command.CommandCode.Should().Be(message.CommandCode);
        command.GetParameters().Should().Equal(message.Parameters.ToArray());

        byte[] encoded = FinsMessage.EncodeCommandFrame(message.Unit, message.Header, command);
        FrameText.Printable(encoded).Should().Be(FrameText.Printable(frame));
    }

    [Theory]
    [MemberData(nameof(GoodCommands))]
    public void Command_vector_unframed_length_matches_the_writer(string name)
    {
        byte[] frame = GoldenVectors.Get(name).FrameBytes();
        FinsCommandMessage message = FinsMessage.ParseCommandFrame(frame);
        FinsMessage.GetCommandLength(message.Header, message.ToCommand()).Should().Be(frame.Length - FrameWriter.FinalOverhead);
    }

    private static FinsCommand Parse(string name, out FinsCommandMessage message)
    {
        message = FinsMessage.ParseCommandFrame(GoldenVectors.Get(name).FrameBytes());
        return message.ToCommand();
    }

    [Fact]
    public void Read_D500_two_words()
    {
        var read = Parse("cs_fins_read_d500", out FinsCommandMessage m).Should().BeOfType<MemoryAreaReadCommand>().Subject;
        m.Unit.Should().Be(0);
        m.Header.Should().Be(FinsHeader.Direct());
        read.Address.Should().Be(new FinsMemoryAddress(FinsMemoryArea.DmWord, 500));
        read.Count.Should().Be(2);
        read.ResponseDataLength.Should().Be(4);
    }

    [Fact]
    public void Published_HR_read_carries_its_0D_in_the_bit_field()
    {
        // The vector's notes read "address 000D, bit 00", but the characters are B2 0000 0D 0001: word 0, bit 0D.
        // Parsing keeps the stray bit so the frame re-encodes byte for byte; the public constructor would refuse it.
        var read = Parse("cs_fins_read_h13", out _).Should().BeOfType<MemoryAreaReadCommand>().Subject;
        read.Address.AreaCode.Should().Be(FinsMemoryArea.WordCode(FinsAreaKind.Holding));
        read.Address.Word.Should().Be(0);
        read.Address.Bit.Should().Be(0x0D);
        read.Address.IsBit.Should().BeFalse();
        read.Count.Should().Be(1);
        var strict = () => new FinsMemoryAddress(FinsMemoryArea.HoldingWord, 0, 0x0D);
        strict.Should().Throw<ArgumentOutOfRangeException>();
    }

    [Fact]
    public void Read_five_CIO_bits()
    {
        var read = Parse("java_fins_read_cio_bits", out _).Should().BeOfType<MemoryAreaReadCommand>().Subject;
        read.Address.Should().Be(new FinsMemoryAddress(FinsMemoryArea.BitCode(FinsAreaKind.Cio), 0, 0));
        read.Address.IsBit.Should().BeTrue();
        read.Count.Should().Be(5);
        read.ResponseDataLength.Should().Be(5);
    }

    [Fact]
    public void Read_D100_two_words()
    {
        var read = Parse("f_0101_cmd", out _).Should().BeOfType<MemoryAreaReadCommand>().Subject;
        read.Address.Should().Be(new FinsMemoryAddress(0x82, 100));
        read.Count.Should().Be(2);
    }

    [Fact]
    public void Write_W10()
    {
        var write = Parse("f_0102_cmd", out _).Should().BeOfType<MemoryAreaWriteCommand>().Subject;
        write.Address.Should().Be(new FinsMemoryAddress(FinsMemoryArea.WorkWord, 10));
        write.Count.Should().Be(1);
        FinsWords.Read(write.Data.Span, write.Count).Should().Equal(0xBEEF);
    }

    [Fact]
    public void Fill_D1000_to_D1009()
    {
        var fill = Parse("f_0103_cmd", out _).Should().BeOfType<MemoryAreaFillCommand>().Subject;
        fill.Address.Should().Be(new FinsMemoryAddress(FinsMemoryArea.DmWord, 1000));
        fill.Count.Should().Be(10);
        fill.Value.Should().Be(0);
    }

    [Fact]
    public void Multiple_read_of_three_items()
    {
        var multi = Parse("f_0104_cmd", out _).Should().BeOfType<MultipleMemoryAreaReadCommand>().Subject;
        multi.Items.Should().Equal(
            new FinsMemoryAddress(FinsMemoryArea.DmWord, 0),
            new FinsMemoryAddress(FinsMemoryArea.CioWord, 1),
            new FinsMemoryAddress(FinsMemoryArea.CioBit, 1, 5));
        multi.ResponseDataLength.Should().Be(3 + 3 + 2);
    }

    [Fact]
    public void Transfer_D0_to_D100()
    {
        var transfer = Parse("f_0105_cmd", out _).Should().BeOfType<MemoryAreaTransferCommand>().Subject;
        transfer.Source.Should().Be(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0));
        transfer.Destination.Should().Be(new FinsMemoryAddress(FinsMemoryArea.DmWord, 100));
        transfer.Count.Should().Be(16);
    }

    [Fact]
    public void Run_in_MONITOR_mode()
    {
        var run = Parse("f_0401_run_monitor", out _).Should().BeOfType<RunCommand>().Subject;
        run.ProgramNumber.Should().Be(RunCommand.AnyProgram);
        run.Mode.Should().Be(FinsCpuMode.Monitor);
        run.Should().Be(new RunCommand(FinsCpuMode.Monitor));
    }

    [Fact]
    public void Stop()
    {
        var stop = Parse("f_0402_stop", out _).Should().BeOfType<StopCommand>().Subject;
        stop.ProgramNumber.Should().Be(0xFFFF);
        stop.Should().Be(new StopCommand());
    }

    [Fact]
    public void Cpu_unit_data_read_with_selector_00()
        => Parse("f_0501_cmd", out _).Should().BeOfType<CpuUnitDataReadCommand>().Which.Selector.Should().Be(0);

    [Fact]
    public void Parameterless_commands()
    {
        Parse("f_0601_cmd", out _).Row.Should().BeSameAs(FinsCommands.CpuUnitStatusRead);
        Parse("f_0701_cmd", out _).Row.Should().BeSameAs(FinsCommands.ClockRead);
        Parse("f_2302_cmd", out _).Row.Should().BeSameAs(FinsCommands.ForcedCancel);
    }

    [Fact]
    public void Cycle_time_read()
        => Parse("f_0620_cmd", out _).Should().BeOfType<CycleTimeReadCommand>().Which.Initialize.Should().BeFalse();

    [Fact]
    public void Clock_write_with_second_and_day_of_week()
    {
        var clock = Parse("f_0702_cmd", out _).Should().BeOfType<ClockWriteCommand>().Subject;
        clock.Time.Should().Be(new DateTime(2024, 5, 17, 13, 45, 30));
        clock.IncludesSecond.Should().BeTrue();
        clock.DayOfWeek.Should().Be(DayOfWeek.Friday);
        clock.Should().Be(new ClockWriteCommand(new DateTime(2024, 5, 17, 13, 45, 30)));
    }

    [Fact]
    public void Error_clear_all()
        => Parse("f_2101_cmd", out _).Should().BeOfType<ErrorClearCommand>().Which.ErrorCode.Should().Be(ErrorClearCommand.AllErrors);

    [Fact]
    public void Error_log_read()
    {
        var log = Parse("f_2102_cmd", out _).Should().BeOfType<ErrorLogReadCommand>().Subject;
        log.FirstRecord.Should().Be(0);
        log.Count.Should().Be(5);
    }

    [Fact]
    public void Forced_set_of_CIO_1_00()
    {
        var force = Parse("f_2301_cmd", out _).Should().BeOfType<ForcedSetResetCommand>().Subject;
        force.Items.Should().Equal(new FinsForcedBit(FinsForceAction.ForceSet, new FinsMemoryAddress(FinsMemoryArea.CioBit, 1, 0)));
    }

    [Fact]
    public void Unit_wait_and_SID()
    {
        Parse("f_sid_wait", out FinsCommandMessage m).Should().BeOfType<MemoryAreaReadCommand>();
        m.Unit.Should().Be(7);
        m.Header.ResponseWait.Should().Be(5);
        m.Header.ResponseWaitTime.Should().Be(TimeSpan.FromMilliseconds(50));
        m.Header.Sid.Should().Be(0x2A);
        m.Header.IsNetwork.Should().BeFalse();
        m.Header.Should().Be(FinsHeader.Direct(sid: 0x2A, responseWait: 5));
    }

    [Fact]
    public void Network_header()
    {
        var read = Parse("f_network_cmd", out FinsCommandMessage m).Should().BeOfType<MemoryAreaReadCommand>().Subject;
        m.Header.IsNetwork.Should().BeTrue();
        m.Header.Should().Be(FinsHeader.Network(dna: 1, da1: 5, da2: 0, sna: 0, sa1: 0, sa2: 0, sid: 1));
        m.Header.Icf.Should().Be(0x80);
        m.Header.Gct.Should().Be(2);
        read.Address.Should().Be(new FinsMemoryAddress(FinsMemoryArea.DmWord, 0));
        read.Count.Should().Be(1);
    }
}
