namespace OmronHostLink.Simulator.Memory;

/// <summary>
/// The forced set and forced reset masks of the words that have forced bits (KS, KR, FK; cleared by KC).
/// Not thread-safe: <see cref="VirtualPlc"/> guards it with its lock.
/// </summary>
internal sealed class ForcedBits
{
    private readonly Dictionary<(PlcArea Area, int Bank, int Word), (ushort Set, ushort Reset)> _masks = new();

    /// <summary>Whether any bit is forced.</summary>
    public bool Any => _masks.Count > 0;

    /// <summary>The number of words with forced bits.</summary>
    public int Count => _masks.Count;

    /// <summary>The value a read sees: forced-set bits on, forced-reset bits off.</summary>
    public ushort Apply(PlcArea area, int bank, int word, ushort value)
    {
        if (_masks.Count == 0 || !_masks.TryGetValue((area, bank, word), out var m))
        {
            return value;
        }

        return (ushort)((value & ~m.Reset) | m.Set);
    }

    /// <summary>Forces one bit on or off.</summary>
    public void Force(PlcArea area, int bank, int word, int bit, bool on)
    {
        ushort mask = (ushort)(1 << bit);
        _masks.TryGetValue((area, bank, word), out var m);
        m = on
            ? ((ushort)(m.Set | mask), (ushort)(m.Reset & ~mask))
            : ((ushort)(m.Set & ~mask), (ushort)(m.Reset | mask));
        _masks[(area, bank, word)] = m;
    }

    /// <summary>Releases the forced state of one bit.</summary>
    public void Release(PlcArea area, int bank, int word, int bit)
    {
        if (!_masks.TryGetValue((area, bank, word), out var m))
        {
            return;
        }

        ushort keep = (ushort)~(1 << bit);
        m = ((ushort)(m.Set & keep), (ushort)(m.Reset & keep));
        if (m.Set == 0 && m.Reset == 0)
        {
            _masks.Remove((area, bank, word));
        }
        else
        {
            _masks[(area, bank, word)] = m;
        }
    }

    /// <summary>Whether the bit is forced, and to which state.</summary>
    public bool? State(PlcArea area, int bank, int word, int bit)
    {
        if (!_masks.TryGetValue((area, bank, word), out var m))
        {
            return null;
        }

        int mask = 1 << bit;
        return (m.Set & mask) != 0 ? true : (m.Reset & mask) != 0 ? false : null;
    }

    /// <summary>Releases every forced bit.</summary>
    public void Clear() => _masks.Clear();
}
