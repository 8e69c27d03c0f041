using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// The tags of a <c>ReadTagsAsync</c> call or of a watch, and the plan in force for them. Planned at once with what is
/// known without asking the PLC (which checks every tag before anything is sent), then again whenever what decides the
/// plan changes: a unit's model learnt with MM (its memory bounds which gaps may be read through), a unit's QQ decided
/// (<see cref="HostLinkClientOptions.UseCompoundRead"/>) or refused. The tags keep their order in every plan.
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
    /// <exception cref="ArgumentException">A tag cannot be read with the view's command set, or its unit's known model lacks it.</exception>
    public PlannedTags(HostLinkUnit unit, PlcTag[] tags)
    {
        _unit = unit;
        _tags = tags;
        _units = tags.Select(t => t.Unit ?? unit.UnitNumber).Distinct().OrderBy(u => u).ToArray();

        // The units QQ could serve: those with a compound read when every unit may use one (only they are asked MM).
        _compoundCandidates = unit.Options.UseCompoundRead == CompoundReadMode.Off || unit.CommandSet != HostLinkCommandSet.CMode
            ? new HashSet<int>()
            : new HashSet<int>(Plan(_units.Select(u => new Basis(u, Known(u), Compound: true)).ToArray())
                .Reads.Where(r => r.Kind == PlannedReadKind.CModeCompound).Select(r => r.Unit));
        _basis = _units.Select(u => new Basis(u, Known(u), _compoundCandidates.Contains(u) && View(u).TryUsesCompoundRead() == true)).ToArray();
        Current = Plan(_basis);
    }

    /// <summary>The plan made last.</summary>
    public ReadPlan Current { get; private set; }

    /// <summary>
    /// The plan for the next read: asks each unit what is not known yet (its model with MM, once, where a model is
    /// detected or QQ decided by it) and plans again when the answers change what the plan rests on. Changed is true the
    /// first time and whenever the plan is new.
    /// </summary>
    /// <exception cref="ArgumentException">A unit's detected model lacks a tag's memory.</exception>
    public async ValueTask<(ReadPlan Plan, bool Changed)> PlanAsync(CancellationToken cancellationToken)
    {
        var basis = new Basis[_units.Length];
        for (int i = 0; i < basis.Length; i++)
        {
            int number = _units[i];
            HostLinkUnit view = View(number);
            PlcModelProfile? model = _unit.Models.Off ? null : await view.GetModelProfileAsync(cancellationToken).ConfigureAwait(false);
            bool compound = _compoundCandidates.Contains(number) && await view.UsesCompoundReadAsync(cancellationToken).ConfigureAwait(false);
            basis[i] = new Basis(number, model, compound);
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
