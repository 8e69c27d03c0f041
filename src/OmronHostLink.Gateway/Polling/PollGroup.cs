using OmronHostLink.Planning;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// A configured poll group on its unit view: the tags its scan class's watch reads for it (the group's words, or its
/// completion flag) and the words last read, decoded as the group's type only when they are logged or published.
/// </summary>
internal sealed class PollGroup
{
    private readonly ushort[] _words;

    public PollGroup(string name, PollGroupOptions options, HostLinkUnit unit, WordOrder wordOrder)
    {
        Name = name;
        Unit = unit;
        UnitNumber = options.Unit;
        Address = PlcAddress.Parse(options.Address);
        Count = options.Count;
        Interval = options.Interval;
        WordOrder = wordOrder;
        PollValueTypes.TryParse(options.Type, out PlcValueType type);
        Type = type;
        Mode = Enum.Parse<PollLogMode>(options.Log, ignoreCase: true);
        AddressText = Address.ToString();

        // Raw words rather than typed tags: the watch plans them into one read, reports the words that changed, and the
        // group's values (text, bits across words, BCD that may not decode) are formatted here as the console does.
        Tags = PollValueTypes.IsCompletionFlag(type, Address)
            ? [new PlcTag(Address, PlcValueType.Bit)]
            : Enumerable.Range(0, PollValueTypes.WordCount(type, Address, Count)).Select(i => new PlcTag(Address.AsWord().Offset(i))).ToArray();
        _words = new ushort[Tags.Count];
    }

    public string Name { get; }

    public HostLinkUnit Unit { get; }

    public int UnitNumber { get; }

    public PlcAddress Address { get; }

    public string AddressText { get; }

    public int Count { get; }

    public TimeSpan Interval { get; }

    public PlcValueType Type { get; }

    public PollLogMode Mode { get; }

    public WordOrder WordOrder { get; }

    /// <summary>What the group's watch reads: one word tag a word, or the completion flag.</summary>
    public IReadOnlyList<PlcTag> Tags { get; }

    /// <summary>The values last logged (OnChange compares with them).</summary>
    public string? LastLogged { get; set; }

    /// <summary>The failure last reported for this group while its PLC answered; null when it reads.</summary>
    public string? Failure { get; set; }

    /// <summary>Takes a changed word (a completion flag as 0 or 1) of the group's tag <paramref name="index"/> from the watch.</summary>
    public void Update(int index, WatchEvent change)
        => _words[index] = Word(change.NewValue);

    /// <summary>Takes the group's words from a read of its <see cref="Tags"/>, in their order.</summary>
    public void Read(IReadOnlyList<PlcTagValue> values)
    {
        for (int i = 0; i < _words.Length; i++)
        {
            _words[i] = values[i].Words[0];
        }
    }

    private static ushort Word(PlcValue value) => value.Type == PlcValueType.Bit ? (ushort)(value.ToBoolean() ? 1 : 0) : value.ToUInt16();

    /// <summary>The values, formatted: <c>1234</c>, <c>[1, 2, 3]</c>, <c>"TEXT"</c>.</summary>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9, or text a byte above 0x7F.</exception>
    public string Format() => Tags[0].IsCompletionFlag
        ? (_words[0] != 0 ? "1" : "0")
        : PollValueTypes.Format(Type, Address, Count, _words, WordOrder);

    /// <summary>The outcome for the outputs: the values last read when <paramref name="quality"/> is good.</summary>
    public TagChange Change(string link, TagQuality quality, DateTimeOffset time, string? error = null)
        => new(link, UnitNumber, Name, AddressText, Type, quality == TagQuality.Good ? TagValues.Decode(Type, Address, Count, _words, WordOrder) : null, quality, time, error);
}
