using System.Buffers.Binary;
using System.Text;
using System.Text.Json;
using OmronHostLink.Capture;

namespace OmronHostLink.Tests.Capture;

/// <summary>The capture files: pcap as the pcap format defines it, JSON lines, and reading both pcap and pcapng back.</summary>
public sealed class CaptureFileTests : IDisposable
{
    private readonly string _dir = Directory.CreateTempSubdirectory("ohl-capture-").FullName;

    private static readonly byte[] Command = Encoding.ASCII.GetBytes(GoldenFrames.Frames("dws_rd_dm_read")[0]);
    private static readonly byte[] Answer = Encoding.ASCII.GetBytes(GoldenFrames.Frames("c_rd_resp_3w")[0]);

    public void Dispose() => Directory.Delete(_dir, recursive: true);

    [Fact]
    public void A_pcap_starts_with_the_classic_header_of_link_type_user0()
    {
        string path = Path.Combine(_dir, "a.pcap");
        using (CaptureWriter writer = CaptureWriter.Create(path))
        {
        }

        byte[] file = File.ReadAllBytes(path);

        // pcap: magic A1B2C3D4 (microseconds), version 2.4, zone 0, sigfigs 0, snaplen, link type 147 = LINKTYPE_USER0; little-endian.
        file.Should().HaveCount(24);
        file.AsSpan(0, 4).ToArray().Should().Equal(0xD4, 0xC3, 0xB2, 0xA1);
        BinaryPrimitives.ReadUInt16LittleEndian(file.AsSpan(4)).Should().Be(2);
        BinaryPrimitives.ReadUInt16LittleEndian(file.AsSpan(6)).Should().Be(4);
        BinaryPrimitives.ReadUInt32LittleEndian(file.AsSpan(20)).Should().Be(147);
    }

    [Fact]
    public void A_record_carries_its_time_direction_flags_and_duration()
    {
        string path = Path.Combine(_dir, "b.pcap");
        var time = new DateTimeOffset(2025, 11, 20, 8, 14, 2, TimeSpan.Zero).AddTicks(1_234_560);
        using (CaptureWriter writer = CaptureWriter.Create(path))
        {
            writer.Write(time, LineDirection.ToPlc, Command, CaptureFlags.None, TimeSpan.FromMilliseconds(17.875));
        }

        byte[] file = File.ReadAllBytes(path);
        ReadOnlySpan<byte> record = file.AsSpan(24);
        BinaryPrimitives.ReadUInt32LittleEndian(record).Should().Be((uint)time.ToUnixTimeSeconds());
        BinaryPrimitives.ReadUInt32LittleEndian(record.Slice(4)).Should().Be(123_456, "the fraction is in microseconds");
        BinaryPrimitives.ReadUInt32LittleEndian(record.Slice(8)).Should().Be((uint)(12 + Command.Length));
        ReadOnlySpan<byte> data = record.Slice(16);
        data.Slice(0, 12).ToArray().Should().Equal((byte)'H', (byte)'L', 1, 1, 0, 0, 0, 0, 0, 0, 0x45, 0xD3); // 17875 µs = 0x45D3
        data.Slice(12).ToArray().Should().Equal(Command);
    }

    [Fact]
    public void A_pcap_reads_back_as_written()
    {
        string path = Path.Combine(_dir, "c.pcap");
        var t0 = DateTimeOffset.UtcNow;
        using (CaptureWriter writer = CaptureWriter.Create(path))
        {
            writer.Write(t0, LineDirection.ToPlc, Command);
            writer.Write(t0.AddMilliseconds(3.5), LineDirection.FromPlc, Answer, CaptureFlags.None, TimeSpan.FromMilliseconds(2));
            writer.Write(t0.AddMilliseconds(9), LineDirection.Unknown, [0x8F, 0x00], CaptureFlags.NotFramed | CaptureFlags.LineError);
        }

        IReadOnlyList<CapturedFrame> frames = CaptureReader.Read(path);

        frames.Select(f => f.Direction).Should().Equal(LineDirection.ToPlc, LineDirection.FromPlc, LineDirection.Unknown);
        frames[0].Bytes.Should().Equal(Command);
        frames[1].Bytes.Should().Equal(Answer);
        frames[1].Duration.Should().Be(TimeSpan.FromMilliseconds(2));
        frames[2].Flags.Should().Be(CaptureFlags.NotFramed | CaptureFlags.LineError);
        (frames[1].Time - frames[0].Time).Should().Be(TimeSpan.FromMilliseconds(3.5));
        frames[0].Time.Should().BeCloseTo(t0, TimeSpan.FromMicroseconds(1));
        frames[0].Unit.Should().Be(0);
        frames[0].Header.Should().Be("RD");
    }

    [Fact]
    public void A_pcapng_as_wireshark_saves_it_reads_back()
    {
        // Built by hand from the pcapng specification: a section header, an interface of link type 147 with nanosecond
        // timestamps (if_tsresol 9), and one enhanced packet block.
        var file = new List<byte>();
        Block(file, 0x0A0D0D0A, [.. U32(0x1A2B3C4D), .. U16(1), .. U16(0), .. U64(ulong.MaxValue)]);
        Block(file, 1, [.. U16(147), .. U16(0), .. U32(65535), .. U16(9), .. U16(1), 9, 0, 0, 0, .. U16(0), .. U16(0)]);
        long ns = 1_763_626_442_123_456_789;
        byte[] data = [(byte)'H', (byte)'L', 1, 2, 0, 0, 0, 0, 0, 0, 0, 0, .. Answer];
        byte[] padded = [.. data, .. new byte[(4 - (data.Length % 4)) % 4]];
        Block(file, 6, [.. U32(0), .. U32((uint)(ns >> 32)), .. U32((uint)ns), .. U32((uint)data.Length), .. U32((uint)data.Length), .. padded]);

        IReadOnlyList<CapturedFrame> frames = CaptureReader.Read(file.ToArray(), "saved.pcapng");

        frames.Should().ContainSingle();
        frames[0].Direction.Should().Be(LineDirection.FromPlc);
        frames[0].Bytes.Should().Equal(Answer);
        frames[0].Time.ToUnixTimeMilliseconds().Should().Be(1_763_626_442_123);
        (frames[0].Time.UtcTicks % TimeSpan.TicksPerMillisecond).Should().Be(4567, "nanoseconds are kept to the 100 ns tick");
    }

    [Fact]
    public void Another_link_type_is_refused_in_words()
    {
        byte[] file = new byte[24];
        BinaryPrimitives.WriteUInt32LittleEndian(file, 0xA1B2C3D4);
        BinaryPrimitives.WriteUInt32LittleEndian(file.AsSpan(20), 1);

        FluentActions.Invoking(() => CaptureReader.Read(file, "ethernet.pcap")).Should().Throw<FormatException>()
            .WithMessage("ethernet.pcap holds records of link type 1, not Host Link records (link type 147, LINKTYPE_USER0, as hostlink writes them).");
    }

    [Fact]
    public void Json_lines_have_one_object_a_frame()
    {
        string path = Path.Combine(_dir, "d.jsonl");
        var t0 = new DateTimeOffset(2025, 11, 20, 8, 14, 2, 118, TimeSpan.Zero);
        using (CaptureWriter writer = CaptureWriter.Create(path))
        {
            writer.Write(t0, LineDirection.ToPlc, Command);
            writer.Write(t0, LineDirection.FromPlc, [0x8F, 0x0D], CaptureFlags.NotFramed);
        }

        string[] lines = File.ReadAllLines(path);

        lines.Should().HaveCount(2);
        JsonElement first = JsonDocument.Parse(lines[0]).RootElement;
        first.GetProperty("time").GetString().Should().Be("2025-11-20T08:14:02.1180000Z");
        first.GetProperty("direction").GetString().Should().Be("toPlc");
        first.GetProperty("unit").GetInt32().Should().Be(0);
        first.GetProperty("header").GetString().Should().Be("RD");
        first.GetProperty("frame").GetString().Should().Be("@00RD0000001057*\r");
        JsonElement second = JsonDocument.Parse(lines[1]).RootElement;
        second.GetProperty("frame").GetString().Should().Be("\u008F\r");
        second.GetProperty("unit").ValueKind.Should().Be(JsonValueKind.Null);
        second.GetProperty("flags").EnumerateArray().Select(f => f.GetString()).Should().Equal("notFramed");
    }

    private static void Block(List<byte> file, uint type, byte[] body)
    {
        uint length = (uint)(12 + body.Length);
        file.AddRange(U32(type));
        file.AddRange(U32(length));
        file.AddRange(body);
        file.AddRange(U32(length));
    }

    private static byte[] U16(ushort v) => [(byte)v, (byte)(v >> 8)];

    private static byte[] U32(uint v) => [(byte)v, (byte)(v >> 8), (byte)(v >> 16), (byte)(v >> 24)];

    private static byte[] U64(ulong v) => [.. U32((uint)v), .. U32((uint)(v >> 32))];
}
