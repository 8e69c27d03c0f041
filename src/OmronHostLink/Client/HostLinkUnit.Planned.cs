using OmronHostLink.Planning;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>Planned reads of many tags: the fewest transactions, computed by <see cref="ReadPlanner"/>.</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// Reads typed tags (scattered, overlapping, in several areas and units) in the fewest transactions, each value
    /// decoded by <see cref="PlcValueCodec"/>: gaps cheaper to read through than another command are read through; with
    /// FINS, isolated words share 0104 MULTIPLE MEMORY AREA READ commands; with C-mode, scattered words and bits share
    /// one QQIR (QQ, the compound read, registered with QQMR the first time) on a unit that uses QQ —
    /// <see cref="HostLinkClientOptions.UseCompoundRead"/>: by default (<see cref="CompoundReadMode.Auto"/>) a unit
    /// whose model lists it, the configured <see cref="HostLinkClientOptions.Model"/> or the one the unit names when
    /// this call asks MM, once; a unit that answers QQ with IC is read by area, this call included. A tag with a unit
    /// number is read through that unit's view on this link; the others from this unit. Each transaction is one
    /// snapshot; the set as a whole is not (for one snapshot of scattered raw words, see <see cref="ReadScatteredAsync"/>).
    /// </summary>
    /// <param name="tags">The tags.</param>
    /// <param name="cancellationToken">Cancels the reads.</param>
    /// <returns>One value per tag, in the order of <paramref name="tags"/>.</returns>
    /// <exception cref="ArgumentException">A tag cannot be read with this view's command set (nothing is sent).</exception>
    public Task<PlcTagValue[]> ReadTagsAsync(IReadOnlyList<PlcTag> tags, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(tags);
        var planned = new PlannedTags(this, tags.ToArray());
        return ReadPlannedAsync(planned, cancellationToken);
    }

    /// <summary>
    /// Reads tags given as text (<c>"D100"</c>, <c>"D102:float"</c>, <c>"CIO10.03"</c>; see <see cref="PlcTag.Parse"/>)
    /// from this unit, planned into the fewest transactions as <see cref="ReadTagsAsync(IReadOnlyList{PlcTag}, CancellationToken)"/> does.
    /// </summary>
    /// <param name="tags">The tag texts.</param>
    /// <param name="cancellationToken">Cancels the reads.</param>
    /// <returns>One value per tag, in the order of <paramref name="tags"/>.</returns>
    /// <exception cref="FormatException">A text is not a tag (nothing is sent).</exception>
    /// <exception cref="ArgumentException">A tag cannot be read with this view's command set (nothing is sent).</exception>
    public Task<PlcTagValue[]> ReadTagsAsync(IReadOnlyList<string> tags, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(tags);
        var parsed = new PlcTag[tags.Count];
        for (int i = 0; i < parsed.Length; i++)
        {
            parsed[i] = PlcTag.Parse(tags[i] ?? throw new ArgumentException($"Tag {i} is null.", nameof(tags)));
        }

        return ReadTagsAsync(parsed, cancellationToken);
    }

    /// <summary>
    /// Executes a plan made by <see cref="ReadPlanner"/> (plan once, poll many times). Each read is sent with the
    /// command the plan chose (C-mode, FINS 0101 or 0104), whatever this view's protocol.
    /// </summary>
    /// <param name="plan">The plan.</param>
    /// <param name="cancellationToken">Cancels the reads.</param>
    /// <returns>One value per tag of the plan, in its order.</returns>
    public async Task<PlcTagValue[]> ReadTagsAsync(ReadPlan plan, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(plan);
        await EnsurePlanAsync(plan, cancellationToken).ConfigureAwait(false);
        var results = new ushort[plan.Reads.Count][];
        for (int r = 0; r < results.Length; r++)
        {
            PlannedRead read = plan.Reads[r];
            HostLinkUnit unit = read.Unit == UnitNumber ? this : new UnitView(Connection, Options, read.Unit, Models, CompoundReads);
            results[r] = await unit.ExecuteAsync(read, cancellationToken).ConfigureAwait(false);
        }

        return plan.Resolve(results, Options.WordOrder);
    }

    /// <summary>
    /// Whether this unit's planned reads use QQ (<see cref="HostLinkClientOptions.UseCompoundRead"/>, decided by
    /// <see cref="ReadPlanner"/>'s one rule with the unit's model): with Auto the model is asked with MM once when it is
    /// not known; a unit that refused QQ never again.
    /// </summary>
    internal async ValueTask<bool> UsesCompoundReadAsync(CancellationToken cancellationToken)
    {
        CompoundReadMode mode = Options.UseCompoundRead;
        if (TryUsesCompoundRead() is { } known)
        {
            return known;
        }

        PlcModelProfile? model = mode == CompoundReadMode.On
            ? await GetModelProfileAsync(cancellationToken).ConfigureAwait(false)
            : await Models.GetForCompoundAsync(UnitNumber, ct => new ValueTask<PlcModel>(ReadModelAsync(ct)), cancellationToken).ConfigureAwait(false);
        return ReadPlanner.UsesCompound(mode, model);
    }

    /// <summary>What <see cref="UsesCompoundReadAsync"/> says without asking the PLC; null when the unit's model must be asked first.</summary>
    internal bool? TryUsesCompoundRead()
    {
        CompoundReadMode mode = Options.UseCompoundRead;
        if (mode == CompoundReadMode.Off || CompoundReads.Refused(UnitNumber))
        {
            return false;
        }

        bool known = mode == CompoundReadMode.On ? Models.TryGet(UnitNumber, out PlcModelProfile? model) : Models.TryGetForCompound(UnitNumber, out model);
        return known ? ReadPlanner.UsesCompound(mode, model) : null;
    }

    private async Task<PlcTagValue[]> ReadPlannedAsync(PlannedTags planned, CancellationToken cancellationToken)
    {
        (ReadPlan plan, _) = await planned.PlanAsync(askPlc: true, cancellationToken).ConfigureAwait(false);
        return await ReadTagsAsync(plan, cancellationToken).ConfigureAwait(false);
    }

    private ValueTask<ushort[]> ExecuteAsync(PlannedRead read, CancellationToken cancellationToken)
    {
        if (!Models.TryGet(UnitNumber, out PlcModelProfile? model))
        {
            return ExecuteOnDetectedModelAsync(read, cancellationToken);
        }

        UnitCommandSet commands = CommandsOf(read);
        if (read.Kind is not (PlannedReadKind.FinsMultiple or PlannedReadKind.CModeCompound))
        {
            read.Start.EnsureRange(read.Count, commands.Kind, forWrite: false);
        }

        EnsureModel(model, read);
        return read.Kind switch
        {
            PlannedReadKind.FinsMultiple => ReadScatteredWordsAsync(read.Items, cancellationToken),
            PlannedReadKind.CModeCompound => ReadCompoundWordsAsync(read, cancellationToken),
            PlannedReadKind.CModeCompletionFlags or PlannedReadKind.FinsCompletionFlags => FlagWordsAsync(commands.ReadCompletionFlagsAsync(this, read.Start, read.Count, model, cancellationToken)),
            _ => commands.ReadWordsAsync(this, read.Start, read.Count, model, cancellationToken),
        };
    }

    /// <summary>The command set of a planned read: the plan names its command by kind, whatever this view's command set.</summary>
    private static UnitCommandSet CommandsOf(PlannedRead read)
        => UnitCommandSet.For(read.Kind is PlannedReadKind.FinsArea or PlannedReadKind.FinsCompletionFlags or PlannedReadKind.FinsMultiple ? HostLinkCommandSet.Fins : HostLinkCommandSet.CMode);

    // A plan may be made without the model; what the model lacks (FINS, memory) is refused here, before the read is sent.
    private static void EnsureModel(PlcModelProfile? model, PlannedRead read)
    {
        UnitCommandSet commands = CommandsOf(read);
        if (read.Kind is PlannedReadKind.FinsMultiple or PlannedReadKind.CModeCompound)
        {
            foreach (PlcAddress item in read.Items)
            {
                commands.EnsureModel(model, item, 1, forWrite: false);
            }

            return;
        }

        commands.EnsureModel(model, read.Start, read.Count, forWrite: false);
    }

    private async ValueTask<ushort[]> ExecuteOnDetectedModelAsync(PlannedRead read, CancellationToken cancellationToken)
    {
        await GetModelProfileAsync(cancellationToken).ConfigureAwait(false);
        return await ExecuteAsync(read, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>
    /// A planned compound read: QQIR, registering first when the unit holds nothing (the first cycle, a reopened link,
    /// a restarted PLC). When another tag set holds the unit's registration, this cycle takes its turn only if the
    /// registration and QQIR cost no more characters than the area reads they replace, and reads those otherwise. A
    /// unit that does not use QQ (<see cref="UsesCompoundReadAsync"/>) always reads by area; one that answers QQ with
    /// an end code saying it has none is read by area from this read on.
    /// </summary>
    private async ValueTask<ushort[]> ReadCompoundWordsAsync(PlannedRead read, CancellationToken cancellationToken)
    {
        var items = new CompoundItem[read.Items.Count];
        for (int i = 0; i < items.Length; i++)
        {
            items[i] = CompoundItem.For(read.Items[i]);
        }

        int fallbackCost = read.Fallback.Sum(r => r.Characters);
        bool contended = CompoundReads.HoldsOther(UnitNumber, items, Connection.Openings);
        if (await UsesCompoundReadAsync(cancellationToken).ConfigureAwait(false) && (!contended || read.RegistrationCharacters + read.Characters <= fallbackCost))
        {
            try
            {
                return await ReadCompoundItemsAsync(items, cancellationToken).ConfigureAwait(false);
            }
            catch (HostLinkEndCodeException e) when (CompoundReadRegistry.MeansNoCompoundRead(e.EndCode))
            {
                // The unit claims QQ and has none (or not as the manuals give it): its area reads, now and from now on.
                CompoundReads.Forget(UnitNumber);
                if (CompoundReads.Refuse(UnitNumber))
                {
                    string claim = Options.UseCompoundRead == CompoundReadMode.Auto && Models.TryGetForCompound(UnitNumber, out PlcModelProfile? named) && named is not null
                        ? $"its model ({named.DisplayName}) lists QQ"
                        : "UseCompoundRead is On";
                    ModelLog.CompoundReadRefused(Models.Logger, UnitNumber, "QQ", $"{e.EndCode.ToCode()} ({e.Meaning})", claim);
                }
            }
        }

        var words = new Dictionary<PlcAddress, ushort>();
        foreach (PlannedRead area in read.Fallback)
        {
            ushort[] values = await ExecuteAsync(area, cancellationToken).ConfigureAwait(false);
            for (int i = 0; i < values.Length; i++)
            {
                words[area.WordAt(i)] = values[i];
            }
        }

        var result = new ushort[items.Length];
        for (int i = 0; i < result.Length; i++)
        {
            PlcAddress item = read.Items[i];
            ushort word = words[item.AsWord()];
            result[i] = item.IsBit ? (PlcWords.GetBit(word, item.Bit) ? (ushort)1 : (ushort)0) : word;
        }

        return result;
    }

    private static async ValueTask<ushort[]> FlagWordsAsync(ValueTask<bool[]> reading)
    {
        bool[] flags = await reading.ConfigureAwait(false);
        return Array.ConvertAll(flags, f => f ? (ushort)1 : (ushort)0);
    }

    private ValueTask<ushort[]> ReadScatteredWordsAsync(IReadOnlyList<PlcAddress> words, CancellationToken cancellationToken)
    {
        var items = new FinsMemoryAddress[words.Count];
        for (int i = 0; i < items.Length; i++)
        {
            words[i].EnsureRange(1, HostLinkCommandSet.Fins, forWrite: false);
            items[i] = FinsAddressing.Word(words[i]);
        }

        var command = new MultipleMemoryAreaReadCommand(items);
        return FinsAsync(
            command,
            static (data, c) =>
            {
                FinsMultipleReadValue[] values = FinsMultipleReadValue.ReadAll(data, c);
                var result = new ushort[values.Length];
                for (int i = 0; i < values.Length; i++)
                {
                    result[i] = values[i].Word;
                }

                return result;
            },
            command,
            cancellationToken);
    }
}
