namespace OmronHostLink.Simulator.Faults;

/// <summary>How many faults of each kind a <see cref="VirtualPlc"/> has injected. Thread-safe.</summary>
public sealed class FaultCounters
{
    private long _frames;
    private long _dropped;
    private long _corrupted;
    private long _noise;
    private long _truncated;
    private long _late;
    private long _outOfTurn;
    private long _echoed;

    /// <summary>Answer frames considered for faults (every frame the PLC sends except the bare CR handshake).</summary>
    public long Frames => Interlocked.Read(ref _frames);

    /// <summary>Answers not sent.</summary>
    public long Dropped => Interlocked.Read(ref _dropped);

    /// <summary>Frames sent with one character changed.</summary>
    public long Corrupted => Interlocked.Read(ref _corrupted);

    /// <summary>Frames sent after noise bytes.</summary>
    public long Noise => Interlocked.Read(ref _noise);

    /// <summary>Frames cut before their CR.</summary>
    public long Truncated => Interlocked.Read(ref _truncated);

    /// <summary>Frames sent late.</summary>
    public long Late => Interlocked.Read(ref _late);

    /// <summary>Frames sent out of turn, after answers to later commands.</summary>
    public long OutOfTurn => Interlocked.Read(ref _outOfTurn);

    /// <summary>Received frames echoed back.</summary>
    public long Echoed => Interlocked.Read(ref _echoed);

    /// <summary>All faults injected.</summary>
    public long Total => Dropped + Corrupted + Noise + Truncated + Late + OutOfTurn + Echoed;

    /// <inheritdoc/>
    public override string ToString()
        => $"frames {Frames}: dropped {Dropped}, corrupted {Corrupted}, noise {Noise}, truncated {Truncated}, late {Late}, out of turn {OutOfTurn}, echoed {Echoed}";

    internal void Count(FaultPlan plan)
    {
        Interlocked.Increment(ref _frames);
        if (plan.Drop)
        {
            Interlocked.Increment(ref _dropped);
            return;
        }

        if (plan.CorruptAt >= 0)
        {
            Interlocked.Increment(ref _corrupted);
        }

        if (plan.Noise is not null)
        {
            Interlocked.Increment(ref _noise);
        }

        if (plan.TruncateTo >= 0)
        {
            Interlocked.Increment(ref _truncated);
        }

        if (plan.Late)
        {
            Interlocked.Increment(ref _late);
        }

        if (plan.OutOfTurn)
        {
            Interlocked.Increment(ref _outOfTurn);
        }

        if (plan.Echo)
        {
            Interlocked.Increment(ref _echoed);
        }
    }
}
