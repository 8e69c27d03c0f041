using OmronHostLink.Transports;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Protocol.Fins;

namespace OmronHostLink.Planning;

/// <summary>
/// Computes the cheapest set of transactions that reads a set of tags: scattered, overlapping, in several areas and
/// units. Pure: no I/O.
/// </summary>
/// <remarks>
/// Cost is counted in characters on the line, both ways, plus the PLC's turnaround per frame exchange expressed in
/// characters. Per unit and area the tags' words are sorted and cut into area reads by dynamic programming, so a gap is
/// read through whenever the extra characters cost less than another command (about 7 words at 9600 bps with no
/// turnaround, more with a turnaround). C-mode reads are one command however long (the answer spans frames); FINS
/// 0101 reads are cut at 269 words (what one FA answer frame holds). With FINS, words that are cheaper as
/// items of a 0104 MULTIPLE MEMORY AREA READ (isolated words, in any area) go into as few 0104 commands as the limit of
/// 135 items (what one FA command frame holds) allows. Timer and counter completion flags (bit tags on <c>T5</c>,
/// <c>C7</c>) are read by their own commands (C-mode RG, FINS 0101 with bit access), apart from the present values.
/// </remarks>
public sealed partial class ReadPlanner
{
    private readonly LineTimingCost _cost;
    private readonly double _turnaroundChars;

    /// <summary>Creates a planner.</summary>
    /// <param name="commandSet">The command set of the reading unit views: C-mode plans area reads only; FINS plans 0101 and 0104.</param>
    /// <param name="timing">The line; null for 9600 bps 7E2.</param>
    /// <param name="turnaround">The PLC's turnaround per frame exchange (what makes another command dearer).</param>
    /// <param name="useMultipleRead">Whether FINS plans may use 0104 MULTIPLE MEMORY AREA READ.</param>
    public ReadPlanner(HostLinkCommandSet commandSet = HostLinkCommandSet.CMode, LineTiming? timing = null, TimeSpan turnaround = default, bool useMultipleRead = true)
    {
        if (commandSet is not (HostLinkCommandSet.CMode or HostLinkCommandSet.Fins))
        {
            throw new ArgumentOutOfRangeException(nameof(commandSet), commandSet, "Not a Host Link command set.");
        }

        if (turnaround < TimeSpan.Zero)
        {
            throw new ArgumentOutOfRangeException(nameof(turnaround), turnaround, "The turnaround cannot be negative.");
        }

        CommandSet = commandSet;
        Timing = timing ?? LineTiming.Default;
        Turnaround = turnaround;
        UseMultipleRead = useMultipleRead;
        _cost = new LineTimingCost(Timing, turnaround);
        _turnaroundChars = turnaround.Ticks / (double)Timing.CharacterTime.Ticks;
    }

    /// <summary>The command set planned for.</summary>
    public HostLinkCommandSet CommandSet { get; }

    /// <summary>The line.</summary>
    public LineTiming Timing { get; }

    /// <summary>The PLC turnaround assumed per frame exchange.</summary>
    public TimeSpan Turnaround { get; }

    /// <summary>Whether FINS plans may use 0104.</summary>
    public bool UseMultipleRead { get; }

    /// <summary>
    /// Whether C-mode plans may use QQ, the compound read: per unit, up to 128 items — scattered words of any area C-mode
    /// reaches, timer/counter PVs (two items each), and bits of CIO, LR, HR and AR whose word no other tag needs —
    /// read with one QQIR where that costs fewer characters than their area reads and replaces more than one of them
    /// (completion flags keep their RG reads). <see cref="CompoundReadMode.Auto"/> (the default, as
    /// <see cref="HostLinkClientOptions.UseCompoundRead"/>'s):
    /// QQ where <see cref="Model"/> lists it, area reads where it lacks it or is not given;
    /// <see cref="CompoundReadMode.On"/>: QQ unless <see cref="Model"/> lacks it; <see cref="CompoundReadMode.Off"/>: never.
    /// </summary>
    public CompoundReadMode UseCompoundRead { get; init; }

    /// <summary>
    /// The PLC model of the units planned for, or null (the default) when it is not known: tags are checked against its
    /// memory, a gap is read through only where the model has every word of it, and with
    /// <see cref="CompoundReadMode.Auto"/> it decides QQ.
    /// </summary>
    public PlcModelProfile? Model { get; init; }

    /// <summary>Per unit, whether QQ may be planned, overriding <see cref="UseCompoundRead"/> (the client's decision, made with each unit's model); null for the mode's.</summary>
    internal Func<int, bool>? CompoundUnits { get; init; }

    /// <summary>Per unit, its model, overriding <see cref="Model"/>; null for <see cref="Model"/>.</summary>
    internal Func<int, PlcModelProfile?>? Models { get; init; }

    /// <summary>
    /// The one rule of <see cref="CompoundReadMode"/>: whether a unit of <paramref name="model"/> (null: not known) is
    /// read with QQ.
    /// </summary>
    internal static bool UsesCompound(CompoundReadMode mode, PlcModelProfile? model) => mode switch
    {
        CompoundReadMode.Auto => model?.SupportsCompoundRead == true,
        CompoundReadMode.On => model?.SupportsCompoundRead != false,
        _ => false,
    };

    private bool PlansCompound(int unit)
        => CommandSet == HostLinkCommandSet.CMode && (CompoundUnits is { } units ? units(unit) : UsesCompound(UseCompoundRead, ModelOf(unit)));

    private PlcModelProfile? ModelOf(int unit) => Models is { } models ? models(unit) : Model;

    /// <summary>Plans the reads of <paramref name="tags"/>.</summary>
    /// <param name="tags">The tags; duplicates and overlaps are read once.</param>
    /// <param name="defaultUnit">The unit of tags that carry none.</param>
    /// <exception cref="ArgumentException">A tag cannot be read with the protocol (C-mode: the work area, D/EM 10000+, T/C 2048+).</exception>
    public ReadPlan Plan(IReadOnlyList<PlcTag> tags, int defaultUnit = 0)
    {
        Guard.NotNull(tags);
        Guard.Unit(defaultUnit);
        var units = new int[tags.Count];
        var compoundNeeds = CommandSet == HostLinkCommandSet.CMode && (CompoundUnits is not null || UseCompoundRead != CompoundReadMode.Off) ? new CompoundNeeds() : null;
        var spaces = new SortedDictionary<(int Unit, PlcArea Area, int Bank), List<(int Start, int End)>>();
        var flagSpaces = new SortedDictionary<(int Unit, PlcArea Area, int Bank), List<(int Start, int End)>>();
        for (int t = 0; t < tags.Count; t++)
        {
            PlcTag tag = tags[t] ?? throw new ArgumentException($"Tag {t} is null.", nameof(tags));
            PlcAddress word = tag.Address.AsWord();
            word.EnsureRange(tag.WordCount, CommandSet, forWrite: false);
            units[t] = tag.Unit ?? defaultUnit;
            ModelOf(units[t])?.EnsureRange(word, tag.WordCount, forWrite: false);
            var key = (units[t], word.Area, word.Bank);
            if (tag.IsCompletionFlag)
            {
                if (!flagSpaces.TryGetValue(key, out List<(int, int)>? flags))
                {
                    flagSpaces[key] = flags = new List<(int, int)>();
                }

                flags.Add((word.Word, word.Word + 1));
                continue;
            }

            if (!spaces.TryGetValue(key, out List<(int, int)>? spans))
            {
                spaces[key] = spans = new List<(int, int)>();
            }

            spans.Add((word.Word, word.Word + tag.WordCount));
            compoundNeeds?.Add(units[t], tag);
        }

        var reads = new List<PlannedRead>();
        var multiple = new SortedDictionary<int, List<PlcAddress[]>>();
        foreach (KeyValuePair<(int Unit, PlcArea Area, int Bank), List<(int Start, int End)>> space in spaces)
        {
            List<(int Start, int End)> clusters = Clusters(space.Value);
            PlanSpace(space.Key.Unit, space.Key.Area, space.Key.Bank, clusters, reads, multiple);
        }

        foreach (KeyValuePair<(int Unit, PlcArea Area, int Bank), List<(int Start, int End)>> space in flagSpaces)
        {
            PlanFlags(space.Key.Unit, space.Key.Area, Clusters(space.Value), reads);
        }

        if (compoundNeeds is not null)
        {
            PlanCompound(spaces, reads, compoundNeeds);
        }

        foreach (KeyValuePair<int, List<PlcAddress[]>> unitItems in multiple)
        {
            foreach (List<PlcAddress> items in Batches(unitItems.Value, MultipleMemoryAreaReadCommand.MaxItems))
            {
                reads.Add(new PlannedRead(PlannedReadKind.FinsMultiple, unitItems.Key, default, items.Count, items.ToArray(), MultipleChars(items.Count), 1));
            }
        }

        return new ReadPlan(tags, units, reads, _cost);
    }

    /// <summary>Characters (both ways) of one C-mode area read of <paramref name="words"/> words, and its frame exchanges.</summary>
    public static int CModeReadCharacters(PlcArea area, int words, out int exchanges)
    {
        CModeArea read = CModeAddressing.AreaOf(area);
        return CModeExchangeCharacters(AreaReadCommand.GetMessageLength(read), AreaReadCommand.MaxAnswerText(read, words), CModeResponse.EndCodeLength, CModeAreaInfo.CharactersPerEntry(read), out exchanges);
    }

    /// <summary>Characters (both ways) of one QQIR of <paramref name="words"/> registered words, and its frame exchanges.</summary>
    public static int CompoundReadCharacters(int words, out int exchanges)
        => CompoundAnswerCharacters(CompoundCommands.DataLength(words, words * CompoundItem.WordAnswerLength), out exchanges);

    /// <summary>Characters (both ways) of one QQIR whose answer data is <paramref name="dataLength"/> characters, and its frame exchanges.</summary>
    internal static int CompoundAnswerCharacters(int dataLength, out int exchanges)
        => CModeExchangeCharacters(CModeCommand.PrefixLength + CompoundCommands.ReadCommand.TextLength, CompoundCommands.AnswerFixed + dataLength, CompoundCommands.AnswerFixed, atom: 1, out exchanges);

    /// <summary>Characters (both ways) of the QQMR registering <paramref name="items"/> items, and its frame exchanges.</summary>
    internal static int CompoundRegisterCharacters(int items, out int exchanges)
    {
        int message = CModeCommand.PrefixLength + CompoundRegisterCommand.GetTextLength(items);
        int fixedLength = CModeCommand.PrefixLength + CompoundRegisterCommand.GetTextLength(1);
        exchanges = FrameWriter.CountFrames(message, fixedLength, CompoundRegisterCommand.ItemAtomLength);
        int answer = CModeResponse.PrefixLength + CompoundCommands.AnswerFixed + FrameWriter.FinalOverhead;
        return FrameWriter.WireLength(message, fixedLength, CompoundRegisterCommand.ItemAtomLength) + (exchanges - 1) + answer;
    }

    /// <summary>Characters (both ways) of one C-mode RG read of <paramref name="flags"/> completion flags, and its frame exchanges.</summary>
    internal static int CModeFlagCharacters(int flags, out int exchanges)
        => CModeExchangeCharacters(AreaReadCommand.GetMessageLength(CModeArea.TimerCounterStatus), AreaReadCommand.MaxAnswerText(CModeArea.TimerCounterStatus, flags), CModeResponse.EndCodeLength, CModeAreaInfo.CharactersPerEntry(CModeArea.TimerCounterStatus), out exchanges);

    /// <summary>Characters (both ways) of one FINS 0101 read of <paramref name="flags"/> completion flags (one byte each).</summary>
    internal static int FinsFlagCharacters(int flags)
        => FinsMessage.DirectCommandFrameLength(MemoryAreaReadCommand.ParametersLength) + FinsMessage.DirectResponseFrameLength(flags * FinsMemoryArea.BitSize);

    /// <summary>Characters (both ways) of one FINS 0101 read of <paramref name="words"/> words (at most 269).</summary>
    public static int FinsReadCharacters(int words)
        => FinsMessage.DirectCommandFrameLength(MemoryAreaReadCommand.ParametersLength) + FinsMessage.DirectResponseFrameLength(words * FinsMemoryArea.WordSize);

    /// <summary>Characters (both ways) of one FINS 0104 read of <paramref name="items"/> words.</summary>
    public static int MultipleChars(int items)
        => FinsMessage.DirectCommandFrameLength(items * FinsMemoryAddress.Length) + FinsMessage.DirectResponseFrameLength(items * MultipleMemoryAreaReadCommand.ResponseItemLength(FinsMemoryArea.WordSize));

    /// <summary>
    /// Characters both ways of one C-mode exchange: the command in one frame, then the answer (<paramref name="answerText"/>
    /// characters after the header, of which <paramref name="answerFixed"/> stay in the first frame) cut into frames
    /// between units of <paramref name="atom"/> characters, and the host's CR asking for each frame after the first.
    /// </summary>
    private static int CModeExchangeCharacters(int commandMessage, int answerText, int answerFixed, int atom, out int exchanges)
    {
        int answer = CModeResponse.PrefixLength + answerText;
        int fixedLength = CModeResponse.PrefixLength + answerFixed;
        exchanges = FrameWriter.CountFrames(answer, fixedLength, atom);
        return commandMessage + FrameWriter.FinalOverhead + FrameWriter.WireLength(answer, fixedLength, atom) + (exchanges - 1);
    }

    /// <summary>
    /// Cuts the runs of words read as 0104 items into commands of at most <paramref name="max"/> items, keeping each run
    /// (the words of one tag, or of neighbouring tags) in one command, one snapshot; only a run longer than a command
    /// holds is cut.
    /// </summary>
    private static IEnumerable<List<PlcAddress>> Batches(List<PlcAddress[]> runs, int max)
    {
        var batch = new List<PlcAddress>();
        foreach (PlcAddress[] run in runs)
        {
            if (batch.Count > 0 && batch.Count + run.Length > max)
            {
                yield return batch;
                batch = new List<PlcAddress>();
            }

            foreach (PlcAddress word in run)
            {
                if (batch.Count == max)
                {
                    yield return batch;
                    batch = new List<PlcAddress>();
                }

                batch.Add(word);
            }
        }

        if (batch.Count > 0)
        {
            yield return batch;
        }
    }

    private static List<(int Start, int End)> Clusters(List<(int Start, int End)> spans)
    {
        spans.Sort((a, b) => a.Start != b.Start ? a.Start.CompareTo(b.Start) : a.End.CompareTo(b.End));
        var clusters = new List<(int Start, int End)>();
        foreach ((int start, int end) in spans)
        {
            if (clusters.Count > 0 && start <= clusters[clusters.Count - 1].End)
            {
                clusters[clusters.Count - 1] = (clusters[clusters.Count - 1].Start, Math.Max(clusters[clusters.Count - 1].End, end));
            }
            else
            {
                clusters.Add((start, end));
            }
        }

        return clusters;
    }

    private double RangeCost(PlcArea area, int words)
    {
        if (CommandSet == HostLinkCommandSet.CMode)
        {
            int chars = CModeReadCharacters(area, words, out int exchanges);
            return chars + (exchanges * _turnaroundChars);
        }

        int full = words / MemoryAreaReadCommand.MaxWords;
        int rest = words % MemoryAreaReadCommand.MaxWords;
        double cost = full * (FinsReadCharacters(MemoryAreaReadCommand.MaxWords) + _turnaroundChars);
        return rest == 0 ? cost : cost + FinsReadCharacters(rest) + _turnaroundChars;
    }

    private void PlanSpace(int unit, PlcArea area, int bank, List<(int Start, int End)> clusters, List<PlannedRead> reads, SortedDictionary<int, List<PlcAddress[]>> multiple)
    {
        bool items = CommandSet == HostLinkCommandSet.Fins && UseMultipleRead;
        int itemChars = MultipleChars(1) - MultipleChars(0);
        int n = clusters.Count;
        PlcModelProfile? model = ModelOf(unit);

        // best[i]: cheapest way to read clusters 0..i-1; from[i] = j: clusters j..i-1 are one area read; -1: cluster i-1 as 0104 items.
        var best = new double[n + 1];
        var from = new int[n + 1];
        for (int i = 1; i <= n; i++)
        {
            best[i] = double.MaxValue;
            for (int j = i - 1; j >= 0; j--)
            {
                // A gap is read through only where the model has all of it (a word it lacks would fail the read).
                if (j < i - 1 && model is not null && !model.Covers(PlcAddress.WordOf(area, clusters[j].End, bank), clusters[j + 1].Start - clusters[j].End))
                {
                    break;
                }

                double cost = best[j] + RangeCost(area, clusters[i - 1].End - clusters[j].Start);
                if (cost < best[i])
                {
                    best[i] = cost;
                    from[i] = j;
                }
            }

            if (items)
            {
                double cost = best[i - 1] + ((clusters[i - 1].End - clusters[i - 1].Start) * itemChars);
                if (cost < best[i])
                {
                    best[i] = cost;
                    from[i] = -1;
                }
            }
        }

        var planned = new List<PlannedRead>();
        var itemRuns = new List<PlcAddress[]>();
        for (int i = n; i > 0;)
        {
            if (from[i] < 0)
            {
                (int start, int end) = clusters[i - 1];
                itemRuns.Add(Enumerable.Range(start, end - start).Select(w => PlcAddress.WordOf(area, w, bank)).ToArray());
                i--;
                continue;
            }

            int j = from[i];
            AddRange(planned, unit, area, bank, clusters[j].Start, clusters[i - 1].End - clusters[j].Start);
            i = j;
        }

        planned.Reverse();
        itemRuns.Reverse();

        // The DP counted 0104 items at their marginal cost; a lone, small batch may still be dearer than reading its
        // clusters as area reads once the 0104 command's own characters are paid. Compare and keep the cheaper.
        int itemCount = itemRuns.Sum(r => r.Length);
        if (itemCount > 0 && !multiple.ContainsKey(unit))
        {
            double asItems = MultipleChars(itemCount) + _turnaroundChars;
            double asRanges = 0;
            var alternative = new List<PlannedRead>();
            foreach (PlcAddress[] run in itemRuns)
            {
                asRanges += RangeCost(area, run.Length);
                AddRange(alternative, unit, area, bank, run[0].Word, run.Length);
            }

            if (asRanges <= asItems)
            {
                planned.AddRange(alternative);
                planned.Sort((a, b) => a.Start.Word.CompareTo(b.Start.Word));
                itemRuns.Clear();
            }
        }

        reads.AddRange(planned);
        if (itemRuns.Count > 0)
        {
            if (!multiple.TryGetValue(unit, out List<PlcAddress[]>? list))
            {
                multiple[unit] = list = new List<PlcAddress[]>();
            }

            list.AddRange(itemRuns);
        }
    }

    /// <summary>
    /// Completion flags: runs of timers (or counters) read with one command each, a gap read through while its flags
    /// cost fewer characters than another command would.
    /// </summary>
    private void PlanFlags(int unit, PlcArea area, List<(int Start, int End)> clusters, List<PlannedRead> reads)
    {
        bool cmode = CommandSet == HostLinkCommandSet.CMode;
        double command = (cmode ? CModeFlagCharacters(0, out _) : FinsFlagCharacters(0)) + _turnaroundChars;
        int perFlag = cmode ? 1 : 2;
        (int start, int end) = clusters[0];
        for (int i = 1; i <= clusters.Count; i++)
        {
            if (i < clusters.Count && (clusters[i].Start - end) * perFlag < command)
            {
                end = clusters[i].End;
                continue;
            }

            for (int done = start; done < end;)
            {
                int n = cmode ? end - done : Math.Min(MemoryAreaReadCommand.MaxBits, end - done);
                PlcAddress first = PlcAddress.WordOf(area, done);
                int exchanges = 1;
                int chars = cmode ? CModeFlagCharacters(n, out exchanges) : FinsFlagCharacters(n);
                reads.Add(new PlannedRead(cmode ? PlannedReadKind.CModeCompletionFlags : PlannedReadKind.FinsCompletionFlags, unit, first, n, Array.Empty<PlcAddress>(), chars, exchanges));
                done += n;
            }

            if (i < clusters.Count)
            {
                (start, end) = clusters[i];
            }
        }
    }

    private void AddRange(List<PlannedRead> reads, int unit, PlcArea area, int bank, int start, int count)
    {
        if (CommandSet == HostLinkCommandSet.CMode)
        {
            int chars = CModeReadCharacters(area, count, out int exchanges);
            reads.Add(new PlannedRead(PlannedReadKind.CModeArea, unit, PlcAddress.WordOf(area, start, bank), count, Array.Empty<PlcAddress>(), chars, exchanges));
            return;
        }

        for (int done = 0; done < count; done += MemoryAreaReadCommand.MaxWords)
        {
            int n = Math.Min(MemoryAreaReadCommand.MaxWords, count - done);
            reads.Add(new PlannedRead(PlannedReadKind.FinsArea, unit, PlcAddress.WordOf(area, start + done, bank), n, Array.Empty<PlcAddress>(), FinsReadCharacters(n), 1));
        }
    }
}
