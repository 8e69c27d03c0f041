using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Tests.Fins;

/// <summary>Response writer → reader round trips, framing and typed data.</summary>
public class FinsResponseRoundTripTests
{
    private static FinsHeader Header(Random r)
        => r.Next(2) == 0
            ? FinsHeader.Direct(r.Next(256), r.Next(16))
            : FinsHeader.Network(r.Next(128), r.Next(256), r.Next(256), r.Next(128), r.Next(256), r.Next(256), r.Next(256), r.Next(8), r.Next(16));

    [Fact]
    public void Response_survives_write_frame_parse()
    {
        var random = new Random(20240517);
        for (int i = 0; i < 500; i++)
        {
            FinsHeader commandHeader = Header(random);
            int unit = random.Next(32);
            var code = (ushort)random.Next(65536);
            var endCode = new FinsEndCode((ushort)random.Next(65536));
            var data = new byte[random.Next(0, FinsMessage.MaxResponseDataLength + 1)];
            random.NextBytes(data);

            byte[] frame = FinsMessage.EncodeResponseFrame(unit, commandHeader, code, endCode, data);
            frame.Length.Should().BeLessThanOrEqualTo(FinsMessage.MaxFrameLength);

            FinsResponse response = FinsResponse.ParseFrame(frame, unit, commandHeader, code);
            response.Unit.Should().Be(unit);
            response.CommandCode.Should().Be(code);
            response.EndCode.Should().Be(endCode);
            response.Header.Should().Be(commandHeader.ToResponseHeader());
            response.Header.Sid.Should().Be(commandHeader.Sid);
            response.Data.ToArray().Should().Equal(data);
        }
    }

    [Fact]
    public void Largest_network_response_is_exactly_1115_characters()
    {
        FinsHeader network = FinsHeader.Network(1, 2, 0, 0, 0, 0);
        FinsMessage.EncodeResponseFrame(0, network, 0x0101, default, new byte[FinsMessage.MaxResponseDataLength]).Length.Should().Be(1115);
        FinsMessage.EncodeResponseFrame(0, FinsHeader.Direct(), 0x0101, default, new byte[FinsMessage.MaxResponseDataLength]).Length.Should().Be(1103);
        var tooLong = () => FinsMessage.EncodeResponseFrame(0, network, 0x0101, default, new byte[FinsMessage.MaxResponseDataLength + 1]);
        tooLong.Should().Throw<ArgumentException>();
    }

    [Fact]
    public void Words_round_trip()
    {
        var random = new Random(1);
        ushort[] words = Enumerable.Range(0, MemoryAreaReadCommand.MaxWords).Select(_ => (ushort)random.Next(65536)).ToArray();
        byte[] data = FinsWords.ToBytes(words);
        FinsWords.Read(data, words.Length).Should().Equal(words);
        var span = new ushort[words.Length];
        FinsWords.Read(data, span);
        span.Should().Equal(words);
    }

    [Fact]
    public void Bits_round_trip_and_reject_values_other_than_00_and_01()
    {
        bool[] bits = { true, false, false, true, true };
        FinsBits.Read(FinsBits.ToBytes(bits), bits.Length).Should().Equal(bits);
        var act = () => FinsBits.Read(new byte[] { 0, 2 }, 2);
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.Malformed);
        var length = () => FinsBits.Read(new byte[] { 0, 1 }, 3);
        length.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public void Multiple_read_values_round_trip()
    {
        var command = new MultipleMemoryAreaReadCommand(new[]
        {
            new FinsMemoryAddress(0x82, 10), new FinsMemoryAddress(0x30, 1, 3), new FinsMemoryAddress(0xDC, 0), new FinsMemoryAddress(0xA3, 7),
        });
        FinsMultipleReadValue[] values = { new(0x82, 0xBEEF), new(0x30, 1), new(0xDC, 0xDEADBEEF), new(0xA3, 0x0102) };
        var data = new byte[command.ResponseDataLength];
        FinsMultipleReadValue.WriteAll(values, data).Should().Be(data.Length);
        FinsMultipleReadValue.ReadAll(data, command).Should().Equal(values);
    }

    [Fact]
    public void Cpu_status_round_trip()
    {
        var status = new FinsCpuStatus(0x01, FinsCpuMode.Run, 0x4000, 0x0020, 0x0003, 0x0101, "SYSTEM FAIL");
        var data = new byte[FinsCpuStatus.Length];
        status.Write(data).Should().Be(FinsCpuStatus.Length);
        FinsCpuStatus.Read(data).Should().BeEquivalentTo(status);
        FinsCpuStatus.Read(data.AsSpan(0, 10)).ErrorMessage.Should().BeEmpty();
        var act = () => FinsCpuStatus.Read(data.AsSpan(0, 11));
        act.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public void Cycle_time_round_trip_in_tenths_of_a_millisecond()
    {
        var cycle = new FinsCycleTime(105, 250, 3);
        var data = new byte[FinsCycleTime.Length];
        cycle.Write(data);
        FinsCycleTime read = FinsCycleTime.Read(data);
        read.Average.Should().Be(TimeSpan.FromMilliseconds(10.5));
        read.Maximum.Should().Be(TimeSpan.FromMilliseconds(25));
        read.Minimum.Should().Be(TimeSpan.FromMilliseconds(0.3));
    }

    [Fact]
    public void Clock_round_trip_and_century_rule()
    {
        var random = new Random(7);
        for (int i = 0; i < 200; i++)
        {
            DateTime t = new DateTime(1970, 1, 1).AddSeconds(random.Next(0, int.MaxValue)).AddYears(random.Next(0, 31));
            var clock = new FinsClock(t);
            var data = new byte[FinsClock.Length];
            clock.Write(data);
            FinsClock.Read(data).Should().Be(clock);
        }

        FinsClock.ExpandYear(69).Should().Be(2069);
        FinsClock.ExpandYear(70).Should().Be(1970);
        FinsClock.ExpandYear(0).Should().Be(2000);
        FinsClock.ExpandYear(99).Should().Be(1999);
        var notBcd = () => FinsClock.Read(new byte[] { 0x24, 0x1A, 0x01, 0, 0, 0, 0 });
        notBcd.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.Malformed);
        var feb30 = () => FinsClock.Read(new byte[] { 0x24, 0x02, 0x30, 0, 0, 0, 0 });
        feb30.Should().Throw<HostLinkFrameException>();
    }

    [Fact]
    public void Error_log_round_trip()
    {
        var log = new FinsErrorLog(20, 3, new[]
        {
            new FinsErrorLogRecord(0x80F1, 0x0000, new DateTime(2024, 5, 17, 13, 45, 30)),
            new FinsErrorLogRecord(0x0008, 0x1234, new DateTime(1998, 1, 2, 3, 4, 5)),
        });
        var data = new byte[log.Length];
        log.Write(data);
        FinsErrorLog read = FinsErrorLog.Read(data);
        read.MaxRecords.Should().Be(20);
        read.StoredRecords.Should().Be(3);
        read.Records.Should().HaveCount(2);
        read.Records[0].ErrorCode.Should().Be(0x80F1);
        read.Records[0].Time.Should().Be(new DateTime(2024, 5, 17, 13, 45, 30));
        read.Records[1].ErrorInfo.Should().Be(0x1234);
        read.Records[1].Time.Should().Be(new DateTime(1998, 1, 2, 3, 4, 5));
        read.Records[1].Raw.ToArray().Should().Equal(log.Records[1].Raw.ToArray());

        var cut = () => FinsErrorLog.Read(data.AsSpan(0, data.Length - 1));
        cut.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public void Error_log_record_with_a_bad_time_keeps_its_raw_bytes()
    {
        byte[] raw = { 0x12, 0x34, 0x00, 0x01, 0x99, 0x99, 0x99, 0x99, 0x99, 0x99 };
        var record = new FinsErrorLogRecord(raw);
        record.ErrorCode.Should().Be(0x1234);
        record.Time.Should().BeNull();
        record.Raw.ToArray().Should().Equal(raw);
    }

    [Fact]
    public void Cpu_unit_data_round_trip()
    {
        var unitData = new FinsCpuUnitData("CJ1M-CPU13", "02.01", new byte[] { 1, 2, 3 });
        var data = new byte[unitData.Length];
        unitData.Write(data);
        data.AsSpan(10, 10).ToArray().Should().OnlyContain(b => b == (byte)' ');
        FinsCpuUnitData read = FinsCpuUnitData.Read(data);
        read.Model.Should().Be("CJ1M-CPU13");
        read.Version.Should().Be("02.01");
        read.Remainder.ToArray().Should().Equal(1, 2, 3);
        var shortData = () => FinsCpuUnitData.Read(data.AsSpan(0, 39));
        shortData.Should().Throw<HostLinkFrameException>().Which.Error.Should().Be(FrameError.WrongLength);
    }

    [Fact]
    public void Host_Link_error_writer_round_trips_through_the_reader()
    {
        foreach (EndCode code in new[] { EndCode.FcsError, EndCode.FormatError, EndCode.FrameLengthError })
        {
            byte[] frame = FinsMessage.EncodeHostLinkErrorFrame(5, code);
            var act = () => FinsResponse.ParseFrame(frame, 5, FinsHeader.Direct(), 0x0101);
            act.Should().Throw<HostLinkEndCodeException>().Which.EndCode.Should().Be(code);
        }

        var ok = () => FinsMessage.EncodeHostLinkErrorFrame(0, EndCode.NormalCompletion);
        ok.Should().Throw<ArgumentException>();
    }
}
