namespace OmronHostLink.Gateway.Writes;

/// <summary>
/// How many writes an output lets wait for their link: at most <see cref="Capacity"/>, each written on its own (at 9600
/// baud a write of a few words takes some 30 ms of the line, which the link's polls share in turn). What would take
/// more is refused at once, whole, and the refusal says how many writes it asked for.
/// </summary>
internal sealed class WriteBacklog
{
    /// <summary>The most writes that may wait: the same for MQTT JSON commands and Sparkplug B DCMD metrics.</summary>
    public const int Capacity = 256;

    private int _waiting;

    /// <summary>How many writes wait now.</summary>
    public int Waiting => Volatile.Read(ref _waiting);

    /// <summary>Takes room for <paramref name="writes"/> writes; false, taking nothing, when they do not fit.</summary>
    public bool TryReserve(int writes)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(writes);
        int waiting = Volatile.Read(ref _waiting);
        while (true)
        {
            if (writes > Capacity - waiting)
            {
                return false;
            }

            int seen = Interlocked.CompareExchange(ref _waiting, waiting + writes, waiting);
            if (seen == waiting)
            {
                return true;
            }

            waiting = seen;
        }
    }

    /// <summary>Gives back the room of <paramref name="writes"/> writes done (or dropped).</summary>
    public void Release(int writes) => Interlocked.Add(ref _waiting, -writes);
}
