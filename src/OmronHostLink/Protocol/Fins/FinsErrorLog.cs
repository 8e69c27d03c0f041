namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The response data of 2102 ERROR LOG READ: maximum records(2), stored records(2), records read(2), then 10 bytes
/// per record (see <see cref="FinsErrorLogRecord"/>).
/// </summary>
public sealed class FinsErrorLog
{
    /// <summary>Bytes before the records.</summary>
    internal const int HeaderLength = 6;

    private readonly FinsErrorLogRecord[] _records;

    /// <summary>Creates the error log data.</summary>
    /// <param name="maxRecords">How many records the PLC's log holds at most.</param>
    /// <param name="storedRecords">How many records are stored.</param>
    /// <param name="records">The records read (at most 53 fit in an FA response).</param>
    /// <exception cref="ArgumentException">Too many records.</exception>
    public FinsErrorLog(int maxRecords, int storedRecords, IEnumerable<FinsErrorLogRecord> records)
    {
        Guard.InRange(maxRecords, 0, ushort.MaxValue);
        Guard.InRange(storedRecords, 0, ushort.MaxValue);
        _records = Guard.NotNull(records).ToArray();
        if (_records.Length > ErrorLogReadCommand.MaxRecords)
        {
            throw new ArgumentException($"At most {ErrorLogReadCommand.MaxRecords} records fit in a Host Link response.", nameof(records));
        }

        MaxRecords = maxRecords;
        StoredRecords = storedRecords;
    }

    /// <summary>How many records the PLC's log holds at most.</summary>
    public int MaxRecords { get; }

    /// <summary>How many records are stored.</summary>
    public int StoredRecords { get; }

    /// <summary>The records read.</summary>
    public IReadOnlyList<FinsErrorLogRecord> Records => _records;

    /// <summary>Bytes <see cref="Write"/> produces.</summary>
    internal int Length => HeaderLength + (_records.Length * FinsErrorLogRecord.Length);

    /// <summary>Decodes the response data.</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: the records do not match their count.</exception>
    internal static FinsErrorLog Read(ReadOnlySpan<byte> data)
    {
        if (data.Length < HeaderLength)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"ERROR LOG READ data holds {data.Length} bytes; the counts alone take {HeaderLength}.");
        }

        int read = FinsBytes.ReadUInt16(data, 4);
        if (read > ErrorLogReadCommand.MaxRecords || data.Length != HeaderLength + (read * FinsErrorLogRecord.Length))
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"ERROR LOG READ announces {read} records but carries {data.Length - HeaderLength} record bytes.");
        }

        var records = new FinsErrorLogRecord[read];
        for (int i = 0; i < read; i++)
        {
            records[i] = new FinsErrorLogRecord(data.Slice(HeaderLength + (i * FinsErrorLogRecord.Length), FinsErrorLogRecord.Length));
        }

        return new FinsErrorLog(FinsBytes.ReadUInt16(data, 0), FinsBytes.ReadUInt16(data, 2), records);
    }

    /// <summary>Encodes the response data.</summary>
    /// <returns><see cref="Length"/>.</returns>
    internal int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the error log.", nameof(destination));
        }

        FinsBytes.WriteUInt16(destination, 0, (ushort)MaxRecords);
        FinsBytes.WriteUInt16(destination, 2, (ushort)StoredRecords);
        FinsBytes.WriteUInt16(destination, 4, (ushort)_records.Length);
        for (int i = 0; i < _records.Length; i++)
        {
            _records[i].Write(destination.Slice(HeaderLength + (i * FinsErrorLogRecord.Length)));
        }

        return Length;
    }
}
