using System.Buffers.Binary;

namespace OmronHostLink.Capture;

/// <summary>
/// The pcap layout of a Host Link capture, as docs/field-diagnosis.md documents it and the Wireshark dissector in
/// tools/wireshark reads it: link type 147 (LINKTYPE_USER0, which pcap reserves for private use), and before each
/// record's bytes a 12-byte header: <c>H</c> <c>L</c>, version 1, the direction (0 unknown, 1 host to PLC, 2 PLC to
/// host), flags (<see cref="CaptureFlags"/>), three zero bytes, and the microseconds from the record's first byte to its
/// last as a big-endian 32-bit number (0 when not known). The record's time is when its last byte crossed the line.
/// </summary>
internal static class CaptureFormat
{
    /// <summary>LINKTYPE_USER0.</summary>
    public const uint LinkType = 147;

    /// <summary>The bytes before each record's data.</summary>
    public const int HeaderLength = 12;

    /// <summary>The version this code writes and reads.</summary>
    public const byte Version = 1;

    /// <summary>The longest record kept: a frame of the longest length a reader accepts, CR, and the header.</summary>
    public const int SnapLength = 65535;

    /// <summary>Writes the record header for <paramref name="direction"/>, <paramref name="flags"/> and <paramref name="duration"/>.</summary>
    public static void WriteHeader(Span<byte> destination, LineDirection direction, CaptureFlags flags, TimeSpan duration)
    {
        destination[0] = (byte)'H';
        destination[1] = (byte)'L';
        destination[2] = Version;
        destination[3] = (byte)direction;
        destination[4] = (byte)flags;
        destination[5] = 0;
        destination[6] = 0;
        destination[7] = 0;
        long micros = duration.Ticks / 10;
        BinaryPrimitives.WriteUInt32BigEndian(destination.Slice(8, 4), micros <= 0 ? 0u : micros >= uint.MaxValue ? uint.MaxValue : (uint)micros);
    }

    /// <summary>Reads a record header; false when the bytes do not start with one this code understands.</summary>
    public static bool TryReadHeader(ReadOnlySpan<byte> record, out LineDirection direction, out CaptureFlags flags, out TimeSpan duration)
    {
        direction = LineDirection.Unknown;
        flags = CaptureFlags.None;
        duration = TimeSpan.Zero;
        if (record.Length < HeaderLength || record[0] != (byte)'H' || record[1] != (byte)'L' || record[2] != Version || record[3] > (byte)LineDirection.FromPlc)
        {
            return false;
        }

        direction = (LineDirection)record[3];
        flags = (CaptureFlags)record[4];
        duration = TimeSpan.FromTicks(BinaryPrimitives.ReadUInt32BigEndian(record.Slice(8, 4)) * 10L);
        return true;
    }
}
