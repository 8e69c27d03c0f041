namespace OmronHostLink.Link;

/// <summary>
/// The link's state between transactions, with the unit it fell out of step with: the one whose late answer may still
/// come, and so the one the resynchronisation fences first.
/// </summary>
internal readonly struct LinkStatus
{
    /// <summary>No unit to fence first: the fence goes to the next request's unit (after a presence probe nobody echoed).</summary>
    public const int AnyUnit = -1;

    public LinkStatus(LinkState state, int unit = 0)
    {
        State = state;
        Unit = unit;
    }

    public LinkState State { get; }

    /// <summary>The unit of the exchange that left the link out of step (meaningful while it needs a resynchronisation).</summary>
    public int Unit { get; }
}
