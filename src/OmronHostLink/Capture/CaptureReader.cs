using System.Buffers.Binary;

namespace OmronHostLink.Capture;

/// <summary>
/// Reads a Host Link capture back: a pcap (microsecond or nanosecond, either byte order) or a pcapng (as Wireshark saves
/// one) whose records are of link type <see cref="CaptureFormat.LinkType"/> with the record header of
/// <see cref="CaptureFormat"/>.
/// </summary>
internal static class CaptureReader
{
    private const uint PcapMicroseconds = 0xA1B2C3D4;
    private const uint PcapNanoseconds = 0xA1B23C4D;
    private const uint SectionHeaderBlock = 0x0A0D0D0A;
    private const uint InterfaceDescriptionBlock = 1;
    private const uint SimplePacketBlock = 3;
    private const uint EnhancedPacketBlock = 6;
    private const uint ByteOrderMagic = 0x1A2B3C4D;

    /// <summary>Reads every record of the capture file <paramref name="path"/>.</summary>
    /// <exception cref="FormatException">The file is not a pcap or pcapng of Host Link records; the message says what it is instead.</exception>
    /// <exception cref="IOException">The file cannot be read.</exception>
    public static IReadOnlyList<CapturedFrame> Read(string path)
    {
        byte[] bytes = File.ReadAllBytes(path);
        return Read(bytes, Path.GetFileName(path));
    }

    /// <summary>Reads every record of a capture held in <paramref name="bytes"/>; <paramref name="name"/> names it in messages.</summary>
    /// <exception cref="FormatException">The bytes are not a pcap or pcapng of Host Link records.</exception>
    public static IReadOnlyList<CapturedFrame> Read(byte[] bytes, string name)
    {
        if (bytes.Length < 24)
        {
            throw new FormatException($"{name} is not a pcap or pcapng capture: it is {bytes.Length} bytes long.");
        }

        uint magic = BinaryPrimitives.ReadUInt32LittleEndian(bytes);
        if (magic == SectionHeaderBlock)
        {
            return ReadPcapng(bytes, name);
        }

        bool little = magic is PcapMicroseconds or PcapNanoseconds;
        uint swapped = BinaryPrimitives.ReadUInt32BigEndian(bytes);
        if (!little && swapped is not (PcapMicroseconds or PcapNanoseconds))
        {
            throw new FormatException($"{name} is not a pcap or pcapng capture (it starts with 0x{swapped:X8}).");
        }

        bool nanoseconds = (little ? magic : swapped) == PcapNanoseconds;
        uint linkType = Read32(bytes, 20, little) & 0x0FFFFFFF;
        CheckLinkType(linkType, name);
        var frames = new List<CapturedFrame>();
        int at = 24;
        while (at + 16 <= bytes.Length)
        {
            long seconds = Read32(bytes, at, little);
            long fraction = Read32(bytes, at + 4, little);
            int included = (int)Read32(bytes, at + 8, little);
            at += 16;
            if (included < 0 || at + included > bytes.Length)
            {
                throw new FormatException($"{name} ends in the middle of record {frames.Count + 1}.");
            }

            long ticks = (seconds * TimeSpan.TicksPerSecond) + (nanoseconds ? fraction / 100 : fraction * 10);
            frames.Add(Record(bytes.AsSpan(at, included), ticks, name, frames.Count + 1));
            at += included;
        }

        return frames;
    }

    private static IReadOnlyList<CapturedFrame> ReadPcapng(byte[] bytes, string name)
    {
        var frames = new List<CapturedFrame>();
        var interfaces = new List<(uint LinkType, long UnitsPerSecond)>();
        bool little = true;
        int at = 0;
        while (at + 12 <= bytes.Length)
        {
            uint type = Read32(bytes, at, little);
            if (type == SectionHeaderBlock)
            {
                uint order = BinaryPrimitives.ReadUInt32LittleEndian(bytes.AsSpan(at + 8));
                little = order == ByteOrderMagic;
                if (!little && BinaryPrimitives.ReadUInt32BigEndian(bytes.AsSpan(at + 8)) != ByteOrderMagic)
                {
                    throw new FormatException($"{name} is not a pcapng capture: its section header has no byte-order magic.");
                }

                interfaces.Clear();
            }

            int length = (int)Read32(bytes, at + 4, little);
            if (length < 12 || at + length > bytes.Length)
            {
                throw new FormatException($"{name} ends in the middle of a pcapng block.");
            }

            ReadOnlySpan<byte> body = bytes.AsSpan(at + 8, length - 12);
            switch (type)
            {
                case InterfaceDescriptionBlock:
                    uint linkType = little ? BinaryPrimitives.ReadUInt16LittleEndian(body) : BinaryPrimitives.ReadUInt16BigEndian(body);
                    interfaces.Add((linkType, Resolution(body.Slice(8), little)));
                    break;
                case EnhancedPacketBlock:
                {
                    int id = (int)Read32(body, 0, little);
                    if (id >= interfaces.Count)
                    {
                        throw new FormatException($"{name}: a packet names interface {id}, which the capture does not describe.");
                    }

                    CheckLinkType(interfaces[id].LinkType, name);
                    ulong units = ((ulong)Read32(body, 4, little) << 32) | Read32(body, 8, little);
                    int captured = (int)Read32(body, 12, little);
                    long perSecond = interfaces[id].UnitsPerSecond;
                    long ticks = (long)(units / (ulong)perSecond * TimeSpan.TicksPerSecond) + (long)(units % (ulong)perSecond * TimeSpan.TicksPerSecond / (ulong)perSecond);
                    frames.Add(Record(body.Slice(20, captured), ticks, name, frames.Count + 1));
                    break;
                }

                case SimplePacketBlock:
                {
                    CheckLinkType(interfaces.Count > 0 ? interfaces[0].LinkType : 0, name);
                    int original = (int)Read32(body, 0, little);
                    frames.Add(Record(body.Slice(4, Math.Min(original, body.Length - 4)), 0, name, frames.Count + 1));
                    break;
                }
            }

            at += length;
        }

        return frames;
    }

    /// <summary>Units a second of an interface's timestamps: its <c>if_tsresol</c> option, else microseconds.</summary>
    private static long Resolution(ReadOnlySpan<byte> options, bool little)
    {
        int at = 0;
        while (at + 4 <= options.Length)
        {
            int code = little ? BinaryPrimitives.ReadUInt16LittleEndian(options.Slice(at)) : BinaryPrimitives.ReadUInt16BigEndian(options.Slice(at));
            int length = little ? BinaryPrimitives.ReadUInt16LittleEndian(options.Slice(at + 2)) : BinaryPrimitives.ReadUInt16BigEndian(options.Slice(at + 2));
            if (code == 0)
            {
                break;
            }

            if (code == 9 && length >= 1 && at + 4 < options.Length)
            {
                byte resolution = options[at + 4];
                int exponent = resolution & 0x7F;
                return (resolution & 0x80) == 0 ? (long)Math.Pow(10, Math.Min(exponent, 18)) : 1L << Math.Min(exponent, 62);
            }

            at += 4 + ((length + 3) & ~3);
        }

        return 1_000_000;
    }

    private static CapturedFrame Record(ReadOnlySpan<byte> record, long unixTicks, string name, int number)
    {
        if (!CaptureFormat.TryReadHeader(record, out LineDirection direction, out CaptureFlags flags, out TimeSpan duration))
        {
            throw new FormatException($"{name}: record {number} does not start with the Host Link record header (H L, version {CaptureFormat.Version}).");
        }

        var time = new DateTimeOffset(DateTimeOffset.FromUnixTimeSeconds(0).UtcTicks + unixTicks, TimeSpan.Zero);
        return new CapturedFrame(time, direction, record.Slice(CaptureFormat.HeaderLength).ToArray(), flags, duration);
    }

    private static void CheckLinkType(uint linkType, string name)
    {
        if (linkType != CaptureFormat.LinkType)
        {
            throw new FormatException($"{name} holds records of link type {linkType}, not Host Link records (link type {CaptureFormat.LinkType}, LINKTYPE_USER0, as hostlink writes them).");
        }
    }

    private static uint Read32(ReadOnlySpan<byte> bytes, int at, bool little)
        => little ? BinaryPrimitives.ReadUInt32LittleEndian(bytes.Slice(at)) : BinaryPrimitives.ReadUInt32BigEndian(bytes.Slice(at));
}
