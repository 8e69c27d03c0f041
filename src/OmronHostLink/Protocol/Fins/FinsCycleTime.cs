namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// The response data of 0620 CYCLE TIME READ (parameter 01): average, maximum and minimum cycle time, 4 bytes each,
/// binary, in units of 0.1 ms [unverified: the unit and the binary (not BCD) coding rest on one manual and one
/// public library].
/// </summary>
public sealed class FinsCycleTime
{
    /// <summary>Bytes of the response data.</summary>
    internal const int Length = 12;

    /// <summary>Creates the cycle times from their raw values (units of 0.1 ms).</summary>
    public FinsCycleTime(uint averageRaw, uint maximumRaw, uint minimumRaw)
    {
        AverageRaw = averageRaw;
        MaximumRaw = maximumRaw;
        MinimumRaw = minimumRaw;
    }

    /// <summary>The average cycle time as received (units of 0.1 ms).</summary>
    public uint AverageRaw { get; }

    /// <summary>The maximum cycle time as received (units of 0.1 ms).</summary>
    public uint MaximumRaw { get; }

    /// <summary>The minimum cycle time as received (units of 0.1 ms).</summary>
    public uint MinimumRaw { get; }

    /// <summary>The average cycle time.</summary>
    public TimeSpan Average => ToTimeSpan(AverageRaw);

    /// <summary>The maximum cycle time.</summary>
    public TimeSpan Maximum => ToTimeSpan(MaximumRaw);

    /// <summary>The minimum cycle time.</summary>
    public TimeSpan Minimum => ToTimeSpan(MinimumRaw);

    /// <summary>Decodes the 12 bytes of response data.</summary>
    /// <exception cref="HostLinkFrameException"><see cref="FrameError.WrongLength"/>: not 12 bytes.</exception>
    internal static FinsCycleTime Read(ReadOnlySpan<byte> data)
    {
        if (data.Length != Length)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"CYCLE TIME READ data holds {data.Length} bytes; it should hold {Length}.");
        }

        return new FinsCycleTime(FinsBytes.ReadUInt32(data, 0), FinsBytes.ReadUInt32(data, 4), FinsBytes.ReadUInt32(data, 8));
    }

    /// <summary>Encodes the 12 bytes of response data.</summary>
    /// <returns><see cref="Length"/>.</returns>
    internal int Write(Span<byte> destination)
    {
        if (destination.Length < Length)
        {
            throw new ArgumentException("The destination is too small for the cycle times.", nameof(destination));
        }

        FinsBytes.WriteUInt32(destination, 0, AverageRaw);
        FinsBytes.WriteUInt32(destination, 4, MaximumRaw);
        FinsBytes.WriteUInt32(destination, 8, MinimumRaw);
        return Length;
    }

    // 0.1 ms = 1,000 ticks of 100 ns.
    private static TimeSpan ToTimeSpan(uint raw) => TimeSpan.FromTicks(raw * 1000L);
}
