namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's message sequence number: 0 in NBIRTH, then one more for every NDATA, DBIRTH, DDATA and DDEATH,
/// 255 wrapping to 0 (specification 3.0, 6.4.1). Not thread-safe: the one publisher of the node's messages owns it.
/// </summary>
internal sealed class SparkplugSequence
{
    private int _next;

    /// <summary>Starts over for a birth: the next number is 0.</summary>
    public void Reset() => _next = 0;

    /// <summary>The number for the next message.</summary>
    public ulong Next()
    {
        int value = _next;
        _next = (_next + 1) & 0xFF;
        return (ulong)value;
    }
}
