using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// What each unit on one link has registered with QQMR, as far as this client knows: a PLC holds one registration per
/// unit, so another tag set (another watch, a <c>ReadTagsAsync</c> call) taking its turn replaces it, and a reopened
/// link or a PLC restart (end code 19 to QQIR) may have lost it. Shared by every unit view of a client; its gate keeps
/// a registration and the QQIR that relies on it together, so two tag sets never read through each other's registration.
/// </summary>
internal sealed class CompoundReadRegistry
{
    private readonly Dictionary<int, (CompoundItem[] Items, long Openings)> _registered = new();

    /// <summary>Held from the check of a unit's registration to the end of the QQIR that relies on it.</summary>
    public SemaphoreSlim Gate { get; } = new(1, 1);

    /// <summary>Whether <paramref name="unit"/> holds exactly <paramref name="items"/>, registered on the link as it is now open.</summary>
    public bool Holds(int unit, IReadOnlyList<CompoundItem> items, long openings)
        => _registered.TryGetValue(unit, out (CompoundItem[] Items, long Openings) r)
            && r.Openings == openings
            && r.Items.AsSpan().SequenceEqual(items is CompoundItem[] a ? a : items.ToArray());

    /// <summary>Whether <paramref name="unit"/> holds another tag set's registration on the link as it is now open (contention).</summary>
    public bool HoldsOther(int unit, IReadOnlyList<CompoundItem> items, long openings)
        => _registered.TryGetValue(unit, out (CompoundItem[] Items, long Openings) r) && r.Openings == openings && !Holds(unit, items, openings);

    /// <summary>Records that <paramref name="unit"/> now holds <paramref name="items"/>.</summary>
    public void Registered(int unit, IReadOnlyList<CompoundItem> items, long openings) => _registered[unit] = (items.ToArray(), openings);

    /// <summary>Forgets what <paramref name="unit"/> holds (a registration failed or was lost).</summary>
    public void Forget(int unit) => _registered.Remove(unit);
}
