namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// One 10-byte record of 2102 ERROR LOG READ: error code(2), error information(2), then minute, second, day, hour,
/// year, month in BCD [unverified: the layout follows the CS/CJ error log area (A100–A199) and one public library,
/// not the manual's own figure]. <see cref="Raw"/> always keeps the bytes as received.
/// </summary>
public sealed class FinsErrorLogRecord
{
    /// <summary>Bytes of one record.</summary>
    internal const int Length = 10;

    private readonly byte[] _raw;

    /// <summary>Creates a record from its 10 raw bytes (copied).</summary>
    /// <exception cref="ArgumentException">Not 10 bytes.</exception>
    internal FinsErrorLogRecord(ReadOnlySpan<byte> raw)
    {
        if (raw.Length != Length)
        {
            throw new ArgumentException($"An error log record takes {Length} bytes; {raw.Length} were given.", nameof(raw));
        }

        _raw = raw.ToArray();
        ErrorCode = FinsBytes.ReadUInt16(raw, 0);
        ErrorInfo = FinsBytes.ReadUInt16(raw, 2);
        if (FinsBytes.TryFromBcd(raw[4], out int minute) && FinsBytes.TryFromBcd(raw[5], out int second)
            && FinsBytes.TryFromBcd(raw[6], out int day) && FinsBytes.TryFromBcd(raw[7], out int hour)
            && FinsBytes.TryFromBcd(raw[8], out int year) && FinsBytes.TryFromBcd(raw[9], out int month)
            && FinsClock.TryCreate(year, month, day, hour, minute, second, out DateTime time))
        {
            Time = time;
        }
    }

    /// <summary>Creates a record from its decoded values.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The year is outside 1970–2069.</exception>
    public FinsErrorLogRecord(ushort errorCode, ushort errorInfo, DateTime time)
        : this(Encode(errorCode, errorInfo, time))
    {
    }

    /// <summary>The error code (error code 1).</summary>
    public ushort ErrorCode { get; }

    /// <summary>The error information (error code 2).</summary>
    public ushort ErrorInfo { get; }

    /// <summary>When the error occurred, or null when the time bytes are not a valid BCD date.</summary>
    public DateTime? Time { get; }

    /// <summary>The 10 bytes as received.</summary>
    public ReadOnlyMemory<byte> Raw => _raw;

    /// <summary>Writes the 10 bytes.</summary>
    internal void Write(Span<byte> destination) => _raw.CopyTo(destination);

    private static byte[] Encode(ushort errorCode, ushort errorInfo, DateTime time)
    {
        FinsClock.CheckYear(time.Year, nameof(time));
        var raw = new byte[Length];
        FinsBytes.WriteUInt16(raw, 0, errorCode);
        FinsBytes.WriteUInt16(raw, 2, errorInfo);
        raw[4] = FinsBytes.ToBcd(time.Minute);
        raw[5] = FinsBytes.ToBcd(time.Second);
        raw[6] = FinsBytes.ToBcd(time.Day);
        raw[7] = FinsBytes.ToBcd(time.Hour);
        raw[8] = FinsBytes.ToBcd(time.Year % 100);
        raw[9] = FinsBytes.ToBcd(time.Month);
        return raw;
    }
}
