using System.Buffers.Binary;

namespace OmronHostLink.Capture;

/// <summary>A classic pcap file (microsecond timestamps, little-endian) of link type <see cref="CaptureFormat.LinkType"/>.</summary>
internal sealed class PcapCaptureWriter : CaptureWriter
{
    private const uint Magic = 0xA1B2C3D4;
    private const int RecordHeaderLength = 16;

    private readonly byte[] _record = new byte[RecordHeaderLength + CaptureFormat.SnapLength];

    public PcapCaptureWriter(Stream file)
        : base(file)
    {
        var header = new byte[24];
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(), Magic);
        BinaryPrimitives.WriteUInt16LittleEndian(header.AsSpan(4), 2);
        BinaryPrimitives.WriteUInt16LittleEndian(header.AsSpan(6), 4);
        BinaryPrimitives.WriteInt32LittleEndian(header.AsSpan(8), 0);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(12), 0);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(16), CaptureFormat.SnapLength);
        BinaryPrimitives.WriteUInt32LittleEndian(header.AsSpan(20), CaptureFormat.LinkType);
        file.Write(header, 0, header.Length);
    }

    protected override void WriteRecord(Stream file, DateTimeOffset time, LineDirection direction, ReadOnlySpan<byte> bytes, CaptureFlags flags, TimeSpan duration)
    {
        int length = Math.Min(bytes.Length, CaptureFormat.SnapLength - CaptureFormat.HeaderLength);
        int included = CaptureFormat.HeaderLength + length;
        long micros = (time.UtcTicks - DateTimeOffset.FromUnixTimeSeconds(0).UtcTicks) / 10;
        Span<byte> record = _record;
        BinaryPrimitives.WriteUInt32LittleEndian(record, (uint)(micros / 1_000_000));
        BinaryPrimitives.WriteUInt32LittleEndian(record.Slice(4), (uint)(micros % 1_000_000));
        BinaryPrimitives.WriteUInt32LittleEndian(record.Slice(8), (uint)included);
        BinaryPrimitives.WriteUInt32LittleEndian(record.Slice(12), (uint)(CaptureFormat.HeaderLength + bytes.Length));
        CaptureFormat.WriteHeader(record.Slice(RecordHeaderLength), direction, flags, duration);
        bytes.Slice(0, length).CopyTo(record.Slice(RecordHeaderLength + CaptureFormat.HeaderLength));
        file.Write(_record, 0, RecordHeaderLength + included);
    }
}
