using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// What each unit on one link has registered with QQMR, as far as this client knows: a PLC holds one registration per
/// unit, so another tag set (another watch, a <c>ReadTagsAsync</c> call) taking its turn replaces it, and a reopened
/// link or a PLC restart (end code 19 to QQIR) may have lost it. Shared by every unit view of a client; each unit's gate
/// keeps a registration and the QQIR that relies on it together, so two tag sets never read through each other's
/// registration.
/// </summary>
/// <remarks>
/// The gate is the unit's, not the link's: a registration is the unit's alone, and a compound read of one unit waiting
/// for another unit's to finish would ask for the line only after reads that asked for it later, so that the link's
/// reads would no longer take the line in the order they asked (which the gateway's line schedule runs).
/// </remarks>
internal sealed class CompoundReadRegistry
{
    private const int Units = HostLinkRules.MaxUnitNumber + 1;
    private readonly Registration?[] _registered = new Registration?[Units];
    private readonly SemaphoreSlim[] _gates = Enumerable.Range(0, Units).Select(_ => new SemaphoreSlim(1, 1)).ToArray();
    private readonly bool[] _refused = new bool[Units];
    private readonly List<Claimant> _claims = new();

    /// <summary>Held from the check of <paramref name="unit"/>'s registration to the end of the QQIR that relies on it.</summary>
    public SemaphoreSlim Gate(int unit) => _gates[unit];

    /// <summary>Whether <paramref name="unit"/> holds exactly <paramref name="items"/>, registered on the link as it is now open.</summary>
    public bool Holds(int unit, IReadOnlyList<CompoundItem> items, long openings)
        => Volatile.Read(ref _registered[unit]) is { } r
            && r.Openings == openings
            && r.Items.AsSpan().SequenceEqual(items is CompoundItem[] a ? a : items.ToArray());

    /// <summary>Whether <paramref name="unit"/> holds another tag set's registration on the link as it is now open (contention).</summary>
    public bool HoldsOther(int unit, IReadOnlyList<CompoundItem> items, long openings)
        => Volatile.Read(ref _registered[unit]) is { } r && r.Openings == openings && !Holds(unit, items, openings);

    /// <summary>Records that <paramref name="unit"/> now holds <paramref name="items"/>.</summary>
    public void Registered(int unit, IReadOnlyList<CompoundItem> items, long openings) => Volatile.Write(ref _registered[unit], new Registration(items.ToArray(), openings));

    /// <summary>Forgets what <paramref name="unit"/> holds (a registration failed or was lost).</summary>
    public void Forget(int unit) => Volatile.Write(ref _registered[unit], null);

    /// <summary>Whether <paramref name="unit"/> answered QQ with an end code that says it has none: it is read by area for the client's life.</summary>
    public bool Refused(int unit) => Volatile.Read(ref _refused[unit]);

    /// <summary>Records that <paramref name="unit"/> has no QQ; true the first time (to log it once).</summary>
    public bool Refuse(int unit)
    {
        lock (_refused)
        {
            if (_refused[unit])
            {
                return false;
            }

            _refused[unit] = true;
            return true;
        }
    }

    /// <summary>
    /// A watch's claim to <paramref name="unit"/>'s one registration: of the watches that would read the unit with QQ,
    /// the one that saves the most characters a second (<paramref name="weight"/>; the earlier on a tie) uses it and the
    /// others read that unit by area, so that they do not take the registration from each other every cycle. Held
    /// until <see cref="Release"/>, or until <paramref name="owner"/> is collected (a watch never enumerated).
    /// </summary>
    public void Claim(object owner, int unit, double weight)
    {
        lock (_claims)
        {
            _claims.Add(new Claimant(new WeakReference<object>(owner), unit, weight));
        }
    }

    /// <summary>Gives up every claim of <paramref name="owner"/>.</summary>
    public void Release(object owner)
    {
        lock (_claims)
        {
            _claims.RemoveAll(c => !c.Owner.TryGetTarget(out object? o) || ReferenceEquals(o, owner));
        }
    }

    /// <summary>
    /// Whether <paramref name="owner"/> may plan QQ for <paramref name="unit"/>: it holds the unit's best claim, or (a
    /// tag set that claims nothing) no watch claims the unit.
    /// </summary>
    public bool MayUse(object owner, int unit)
    {
        lock (_claims)
        {
            _claims.RemoveAll(c => !c.Owner.TryGetTarget(out _));
            Claimant? best = null;
            foreach (Claimant claim in _claims)
            {
                if (claim.Unit == unit && (best is null || claim.Weight > best.Weight))
                {
                    best = claim;
                }
            }

            return best is null || (best.Owner.TryGetTarget(out object? o) && ReferenceEquals(o, owner));
        }
    }

    /// <summary>
    /// Whether an end code answering QQMR or QQIR says the unit has no QQ as it is used here (IC, 16: not supported;
    /// 14, 18: a format or length it does not take), rather than a word it lacks or a registration it lost.
    /// </summary>
    public static bool MeansNoCompoundRead(EndCode code)
        => code.Category() is EndCodeCategory.NotSupported or EndCodeCategory.Format or EndCodeCategory.Length;

    // In the order claimed: the earlier wins a tie.
    private sealed record Claimant(WeakReference<object> Owner, int Unit, double Weight);

    // Replaced whole, never changed: read without the unit's gate (to judge contention) it is one registration or another.
    private sealed record Registration(CompoundItem[] Items, long Openings);
}
