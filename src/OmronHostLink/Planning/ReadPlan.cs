namespace OmronHostLink.Planning;

/// <summary>The command a <see cref="PlannedRead"/> uses.</summary>
public enum PlannedReadKind
{
    /// <summary>One C-mode area read (RR, RH, RJ, RD, RC, RE), multi-frame when long: one transaction, one snapshot.</summary>
    CModeArea,

    /// <summary>One FINS 0101 MEMORY AREA READ of at most 269 words (what one FA answer frame holds).</summary>
    FinsArea,

    /// <summary>One FINS 0104 MULTIPLE MEMORY AREA READ of scattered words.</summary>
    FinsMultiple,

    /// <summary>One C-mode RG read of timer/counter completion flags, one character a flag; each flag is returned as a word 0 or 1.</summary>
    CModeCompletionFlags,

    /// <summary>One FINS 0101 read of timer/counter completion flags (bit access); each flag is returned as a word 0 or 1.</summary>
    FinsCompletionFlags,

    /// <summary>
    /// One C-mode QQIR of scattered words, timer/counter PVs and bits registered with QQMR (QQ, the compound read): at
    /// most 128 items of one unit, one snapshot. The registration is sent when the unit does not hold it; a cycle whose
    /// registration would cost more than the area reads it replaces reads those instead.
    /// </summary>
    CModeCompound,
}

/// <summary>One transaction of a <see cref="ReadPlan"/>.</summary>
public sealed class PlannedRead
{
    internal PlannedRead(PlannedReadKind kind, int unit, PlcAddress start, int count, IReadOnlyList<PlcAddress> items, int characters, int exchanges, IReadOnlyList<PlannedRead>? fallback = null, int registrationCharacters = 0)
    {
        Fallback = fallback ?? Array.Empty<PlannedRead>();
        RegistrationCharacters = registrationCharacters;
        Kind = kind;
        Unit = unit;
        Start = start;
        Count = count;
        Items = items;
        Characters = characters;
        Exchanges = exchanges;
    }

    /// <summary>The command used.</summary>
    public PlannedReadKind Kind { get; }

    /// <summary>The unit the command goes to.</summary>
    public int Unit { get; }

    /// <summary>The first word of an area read, or the first timer/counter of a completion flag read (unused for <see cref="PlannedReadKind.FinsMultiple"/>).</summary>
    public PlcAddress Start { get; }

    /// <summary>The number of words (or completion flags) read.</summary>
    public int Count { get; }

    /// <summary>Whether the read returns timer/counter completion flags (as words 0 or 1) rather than words.</summary>
    public bool IsCompletionFlags => Kind is PlannedReadKind.CModeCompletionFlags or PlannedReadKind.FinsCompletionFlags;

    /// <summary>
    /// The words of a <see cref="PlannedReadKind.FinsMultiple"/> or <see cref="PlannedReadKind.CModeCompound"/> read, in
    /// order (a compound read's bit items are bit addresses, read as 0 or 1); empty for area reads.
    /// </summary>
    public IReadOnlyList<PlcAddress> Items { get; }

    /// <summary>Characters on the line both ways (command, answer frames, CR delimiters).</summary>
    public int Characters { get; }

    /// <summary>Frame exchanges (each costs a PLC turnaround): 1, or more for a multi-frame C-mode answer.</summary>
    public int Exchanges { get; }

    /// <summary>The address of the <paramref name="index"/>-th word (or bit) this read returns.</summary>
    public PlcAddress WordAt(int index) => Kind is PlannedReadKind.FinsMultiple or PlannedReadKind.CModeCompound ? Items[index] : Start.Offset(index);

    /// <summary>A compound read's area reads of the same words, for a cycle that would otherwise pay the registration.</summary>
    internal IReadOnlyList<PlannedRead> Fallback { get; }

    /// <summary>Characters of a compound read's QQMR registration (both ways), paid when the unit does not hold it.</summary>
    internal int RegistrationCharacters { get; }

    /// <inheritdoc/>
    public override string ToString() => Kind switch
    {
        PlannedReadKind.FinsMultiple => $"unit {Unit:D2} 0104 × {Count}",
        PlannedReadKind.CModeCompound => $"unit {Unit:D2} C-mode QQIR × {Count}",
        PlannedReadKind.CModeCompletionFlags => $"unit {Unit:D2} C-mode RG {Start} × {Count} flags",
        PlannedReadKind.FinsCompletionFlags => $"unit {Unit:D2} 0101 {Start} × {Count} flags",
        _ => $"unit {Unit:D2} {(Kind == PlannedReadKind.CModeArea ? "C-mode" : "0101")} {Start} × {Count}",
    };
}

/// <summary>
/// The transactions that read a set of tags, from <see cref="ReadPlanner.Plan"/>. Pure data: execute the reads (for
/// example with <c>HostLinkUnit.ReadTagsAsync(ReadPlan, CancellationToken)</c>) and turn their words into tag values
/// with <see cref="Resolve"/>.
/// </summary>
public sealed class ReadPlan
{
    internal ReadPlan(IReadOnlyList<PlcTag> tags, int[] tagUnits, IReadOnlyList<PlannedRead> reads, LineTimingCost cost)
    {
        Tags = tags;
        TagUnits = tagUnits;
        Reads = reads;
        Cost = cost;
    }

    /// <summary>The tags, in the order values are returned.</summary>
    public IReadOnlyList<PlcTag> Tags { get; }

    /// <summary>The transactions, grouped by unit.</summary>
    public IReadOnlyList<PlannedRead> Reads { get; }

    /// <summary>The number of transactions.</summary>
    public int TransactionCount => Reads.Count;

    /// <summary>Characters on the line, both ways, for the whole plan.</summary>
    public int Characters => Reads.Sum(r => r.Characters);

    /// <summary>Frame exchanges (PLC turnarounds) for the whole plan.</summary>
    public int Exchanges => Reads.Sum(r => r.Exchanges);

    /// <summary>The least time the plan takes on the line: characters × character time + exchanges × turnaround.</summary>
    public TimeSpan EstimatedTime => Cost.Time(Characters, Exchanges);

    internal int[] TagUnits { get; }

    internal LineTimingCost Cost { get; }

    /// <summary>
    /// One line for logs: <c>3 reads (1 QQIR of 57 items, 2 C-mode area reads), 412 characters, 472 ms at 9600 bps</c>
    /// (the least time on the line, as <see cref="EstimatedTime"/>).
    /// </summary>
    public override string ToString()
    {
        string kinds = string.Join(", ", Reads.GroupBy(r => r.Kind).Select(g => Describe(g.Key, g.Count(), g.Sum(r => r.Count))));
        string reads = TransactionCount == 1 ? "read" : "reads";
        string time = EstimatedTime.TotalMilliseconds.ToString("0", System.Globalization.CultureInfo.InvariantCulture);
        return $"{TransactionCount} {reads}{(kinds.Length == 0 ? "" : $" ({kinds})")}, {Characters} characters, {time} ms at {Cost.Timing.BaudRate} bps";
    }

    private static string Describe(PlannedReadKind kind, int reads, int items)
    {
        string s = reads == 1 ? "" : "s";
        return kind switch
        {
            PlannedReadKind.CModeCompound => $"{reads} QQIR{s} of {items} items",
            PlannedReadKind.FinsMultiple => $"{reads} FINS 0104 read{s} of {items} words",
            PlannedReadKind.CModeCompletionFlags => $"{reads} C-mode RG read{s}",
            PlannedReadKind.FinsCompletionFlags => $"{reads} FINS completion flag read{s}",
            PlannedReadKind.FinsArea => $"{reads} FINS 0101 read{s}",
            _ => $"{reads} C-mode area read{s}",
        };
    }

    /// <summary>Turns the words of every read (in <see cref="Reads"/> order) into one value per tag (in <see cref="Tags"/> order).</summary>
    /// <param name="results">The words each read returned (for a completion flag read, one word 0 or 1 a flag).</param>
    /// <param name="order">How 32-bit values lie in two words.</param>
    /// <exception cref="ArgumentException">The results do not match the reads.</exception>
    public PlcTagValue[] Resolve(IReadOnlyList<ushort[]> results, WordOrder order = WordOrder.LowWordFirst)
    {
        Guard.NotNull(results);
        if (results.Count != Reads.Count)
        {
            throw new ArgumentException($"The plan has {Reads.Count} reads; {results.Count} results were given.", nameof(results));
        }

        var words = new Dictionary<long, ushort>();
        for (int r = 0; r < Reads.Count; r++)
        {
            PlannedRead read = Reads[r];
            ushort[] data = results[r] ?? throw new ArgumentException($"Result {r} is null.", nameof(results));
            if (data.Length != read.Count)
            {
                throw new ArgumentException($"Read {r} ({read}) returns {read.Count} words; its result holds {data.Length}.", nameof(results));
            }

            for (int i = 0; i < data.Length; i++)
            {
                words[Key(read.Unit, read.WordAt(i), read.IsCompletionFlags)] = data[i];
            }
        }

        var values = new PlcTagValue[Tags.Count];
        for (int t = 0; t < Tags.Count; t++)
        {
            PlcTag tag = Tags[t];
            var raw = new ushort[tag.WordCount];
            if (tag.Address.IsBit && words.TryGetValue(Key(TagUnits[t], tag.Address), out ushort bit))
            {
                // Read as a bit alone (a QQ bit item): its word as far as it was read, the tag's bit.
                raw[0] = (ushort)(bit << tag.Address.Bit);
            }
            else
            {
                for (int i = 0; i < raw.Length; i++)
                {
                    raw[i] = words[Key(TagUnits[t], tag.Address.AsWord().Offset(i), tag.IsCompletionFlag)];
                }
            }

            values[t] = new PlcTagValue(tag, raw, Decode(tag, raw, order));
        }

        return values;
    }

    // A timer's completion flag and its present value share an address, as a word and a bit read alone do: the flag
    // and the bit number keep them apart.
    internal static long Key(int unit, PlcAddress address, bool completionFlag = false)
        => (completionFlag ? 1L << 48 : 0) | ((address.IsBit ? address.Bit + 1L : 0) << 52) | ((long)unit << 40) | ((long)address.Area << 32) | ((long)address.Bank << 24) | (uint)address.Word;

    private static object Decode(PlcTag tag, ushort[] raw, WordOrder order)
        => PlcValueCodec.Decode(tag.Type, raw, order, tag.Address.IsBit ? tag.Address.Bit : 0).ToObject();
}

/// <summary>Turns characters and exchanges into time for a line.</summary>
internal readonly struct LineTimingCost
{
    public LineTimingCost(Transports.LineTiming timing, TimeSpan turnaround)
    {
        Timing = timing;
        Turnaround = turnaround;
    }

    public Transports.LineTiming Timing { get; }

    public TimeSpan Turnaround { get; }

    public TimeSpan Time(int characters, int exchanges)
        => Timing.WireTime(characters) + TimeSpan.FromTicks(Turnaround.Ticks * exchanges);
}
