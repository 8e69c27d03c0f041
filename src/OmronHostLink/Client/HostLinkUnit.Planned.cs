using OmronHostLink.Planning;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink;

/// <summary>Planned reads of many tags: the fewest transactions, computed by <see cref="ReadPlanner"/>.</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// Reads many tags (scattered, overlapping, in several areas and units) in the fewest transactions: gaps cheaper
    /// to read through than another command are read through, and with FINS, isolated words share 0104 MULTIPLE
    /// MEMORY AREA READ commands. A tag with a unit number is read through that unit's view on this link; the others
    /// from this unit. Each transaction is one snapshot; the set as a whole is not.
    /// </summary>
    /// <param name="tags">The tags.</param>
    /// <param name="cancellationToken">Cancels the reads.</param>
    /// <returns>One value per tag, in the order of <paramref name="tags"/>.</returns>
    /// <exception cref="ArgumentException">A tag cannot be read with this view's protocol (nothing is sent).</exception>
    public ValueTask<PlcTagValue[]> ReadManyAsync(IReadOnlyList<PlcTag> tags, CancellationToken cancellationToken = default)
    {
        var planner = new ReadPlanner(Options.Protocol, LineTiming);
        return ReadManyAsync(planner.Plan(tags, UnitNumber), cancellationToken);
    }

    /// <summary>
    /// Executes a plan made by <see cref="ReadPlanner"/> (plan once, poll many times). Each read is sent with the
    /// command the plan chose (C-mode, FINS 0101 or 0104), whatever this view's protocol.
    /// </summary>
    /// <param name="plan">The plan.</param>
    /// <param name="cancellationToken">Cancels the reads.</param>
    /// <returns>One value per tag of the plan, in its order.</returns>
    public async ValueTask<PlcTagValue[]> ReadManyAsync(ReadPlan plan, CancellationToken cancellationToken = default)
    {
        Guard.NotNull(plan);
        var results = new ushort[plan.Reads.Count][];
        for (int r = 0; r < results.Length; r++)
        {
            PlannedRead read = plan.Reads[r];
            HostLinkUnit unit = read.Unit == UnitNumber ? this : new UnitView(Connection, Options, read.Unit);
            results[r] = await unit.ExecuteAsync(read, cancellationToken).ConfigureAwait(false);
        }

        return plan.Resolve(results, Options.WordOrder);
    }

    private ValueTask<ushort[]> ExecuteAsync(PlannedRead read, CancellationToken cancellationToken)
    {
        switch (read.Kind)
        {
            case PlannedReadKind.FinsMultiple:
                return ReadMultipleWordsAsync(read.Items, cancellationToken);
            case PlannedReadKind.FinsArea:
                read.Start.EnsureRange(read.Count, HostLinkProtocol.Fins, forWrite: false);
                return FinsReadWordsAsync(read.Start, read.Count, cancellationToken);
            default:
                read.Start.EnsureRange(read.Count, HostLinkProtocol.CMode, forWrite: false);
                return CModeReadWordsAsync(read.Start, read.Count, cancellationToken);
        }
    }

    private ValueTask<ushort[]> ReadMultipleWordsAsync(IReadOnlyList<PlcAddress> words, CancellationToken cancellationToken)
    {
        var items = new FinsMemoryAddress[words.Count];
        for (int i = 0; i < items.Length; i++)
        {
            words[i].EnsureRange(1, HostLinkProtocol.Fins, forWrite: false);
            items[i] = FinsAddressing.Word(words[i]);
        }

        var command = new MultipleMemoryAreaReadCommand(items);
        return FinsAsync(
            command,
            command.ResponseDataLength,
            CommandEffect.ReadOnly,
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
