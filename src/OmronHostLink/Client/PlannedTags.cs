using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// The tags of a <c>ReadTagsAsync</c> call or of a watch, and the plan in force for them. Planned at once with what is
/// known without asking the PLC (which checks every tag before anything is sent), then again whenever what decides the
/// plan changes: a unit's model learnt (its memory bounds which gaps may be read through), a unit's QQ decided
/// (<see cref="HostLinkClientOptions.UseCompoundRead"/>, with MM where the model must be asked) or refused, or the
/// unit's one QQ registration claimed by another watch. The tags keep their order in every plan.
/// </summary>
internal sealed class PlannedTags
{
    private readonly HostLinkUnit _unit;
    private readonly PlcTag[] _tags;
    private readonly int[] _units;
    private readonly HashSet<int> _compoundCandidates;
    private Basis[] _basis;
    private bool _reported;

    /// <summary>Plans <paramref name="tags"/> for reads through <paramref name="unit"/> (tags without a unit from it).</summary>
    /// <param name="unit">The view the reads go through.</param>
    /// <param name="tags">The tags.</param>
    /// <param name="interval">
    /// For a watch, its interval: the watch claims the QQ registration of each unit QQ would serve, weighed by the
    /// characters it saves a second (see <see cref="CompoundReadRegistry.Claim"/>); null for a single read, which
    /// claims nothing and uses QQ only on a unit no watch claims.
    /// </param>
    /// <exception cref="ArgumentException">A tag cannot be read with the view's command set, or its unit's known model lacks it.</exception>
    public PlannedTags(HostLinkUnit unit, PlcTag[] tags, TimeSpan? interval = null)
    {
        _unit = unit;
        _tags = tags;
        _units = tags.Select(t => t.Unit ?? unit.UnitNumber).Distinct().OrderBy(u => u).ToArray();
        _compoundCandidates = new HashSet<int>();
        if (unit.Options.UseCompoundRead != CompoundReadMode.Off && unit.CommandSet == HostLinkCommandSet.CMode)
        {
            // The units QQ could serve: those with a compound read when every unit may use one (only they are asked MM).
            ReadPlan areas = Plan(_units.Select(u => new Basis(u, Known(u), Compound: false)).ToArray());
            ReadPlan compound = Plan(_units.Select(u => new Basis(u, Known(u), Compound: true)).ToArray());
            foreach (int candidate in compound.Reads.Where(r => r.Kind == PlannedReadKind.CModeCompound).Select(r => r.Unit).Distinct())
            {
                _compoundCandidates.Add(candidate);
                if (interval is { } every)
                {
                    int saved = areas.Reads.Where(r => r.Unit == candidate).Sum(r => r.Characters) - compound.Reads.Where(r => r.Unit == candidate).Sum(r => r.Characters);
                    unit.CompoundReads.Claim(this, candidate, saved / Math.Max(every.TotalSeconds, areas.EstimatedTime.TotalSeconds));
                }
            }
        }

        _basis = _units.Select(u => new Basis(u, Known(u), Compound(u, View(u).TryUsesCompoundRead() == true))).ToArray();
        Current = Plan(_basis);
    }

    /// <summary>The plan made last.</summary>
    public ReadPlan Current { get; private set; }

    /// <summary>
    /// The plan for the next read, and whether it is new (true the first time). With <paramref name="askPlc"/> each
    /// unit is asked what is not known yet (its model with MM, once, where a model is detected or QQ decided by it);
    /// without, only what is known is used (a watch asks once its unit has answered a read, so that a silent unit costs
    /// no more than its reads).
    /// </summary>
    /// <exception cref="ArgumentException">A unit's detected model lacks a tag's memory.</exception>
    public async ValueTask<(ReadPlan Plan, bool Changed)> PlanAsync(bool askPlc, CancellationToken cancellationToken)
    {
        var basis = new Basis[_units.Length];
        for (int i = 0; i < basis.Length; i++)
        {
            int number = _units[i];
            HostLinkUnit view = View(number);
            PlcModelProfile? model = askPlc && !_unit.Models.Off ? await view.GetModelProfileAsync(cancellationToken).ConfigureAwait(false) : Known(number);
            bool compound = _compoundCandidates.Contains(number)
                && (askPlc ? await view.UsesCompoundReadAsync(cancellationToken).ConfigureAwait(false) : view.TryUsesCompoundRead() == true);
            basis[i] = new Basis(number, model, Compound(number, compound));
        }

        bool changed = !_reported;
        _reported = true;
        if (!basis.AsSpan().SequenceEqual(_basis))
        {
            _basis = basis;
            Current = Plan(basis);
            changed = true;
        }

        return (Current, changed);
    }

    /// <summary>Gives up this tag set's claims (a watch that ends).</summary>
    public void Release() => _unit.CompoundReads.Release(this);

    private bool Compound(int unit, bool usesCompoundRead)
        => usesCompoundRead && _compoundCandidates.Contains(unit) && _unit.CompoundReads.MayUse(this, unit);

    private PlcModelProfile? Known(int unit) => _unit.Models.TryGet(unit, out PlcModelProfile? model) ? model : null;

    private HostLinkUnit View(int unit) => unit == _unit.UnitNumber ? _unit : _unit.Unit(unit);

    private ReadPlan Plan(Basis[] basis)
    {
        var planner = new ReadPlanner(_unit.CommandSet, _unit.LineTiming)
        {
            UseCompoundRead = _unit.Options.UseCompoundRead,
            CompoundUnits = u => Array.Find(basis, b => b.Unit == u).Compound,
            Models = u => Array.Find(basis, b => b.Unit == u).Model,
        };
        return planner.Plan(_tags, _unit.UnitNumber);
    }

    /// <summary>What a unit's reads are planned with: its model (null: not known or not checked) and whether it uses QQ.</summary>
    private readonly record struct Basis(int Unit, PlcModelProfile? Model, bool Compound);
}
