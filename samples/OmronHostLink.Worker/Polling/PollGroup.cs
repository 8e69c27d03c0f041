using OmronHostLink.Worker.Configuration;
using OmronHostLink.Worker.Mqtt;

namespace OmronHostLink.Worker.Polling;

/// <summary>A configured poll group bound to its unit view on the link's client.</summary>
internal sealed class PollGroup
{
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
        Words = PollValueTypes.WordCount(type, Address, Count);
        AddressText = Address.ToString();
    }

    public string Name { get; }

    public HostLinkUnit Unit { get; }

    public int UnitNumber { get; }

    public PlcAddress Address { get; }

    public string AddressText { get; }

    public int Count { get; }

    public int Words { get; }

    public TimeSpan Interval { get; }

    public PlcValueType Type { get; }

    public PollLogMode Mode { get; }

    public WordOrder WordOrder { get; }

    /// <summary>The values last logged (OnChange compares with them).</summary>
    public string? LastLogged { get; set; }

    /// <summary>The failure last reported for this group while its PLC answered; null when it reads.</summary>
    public string? Failure { get; set; }

    /// <summary>The words of the last successful read (a completion flag as one word, 0 or 1), for a tag sink.</summary>
    public ushort[]? LastWords { get; private set; }

    /// <summary>Reads the group and formats its values.</summary>
    public async ValueTask<string> ReadAsync(CancellationToken cancellationToken)
    {
        if (PollValueTypes.IsCompletionFlag(Type, Address))
        {
            bool flag = await Unit.ReadBitAsync(Address, cancellationToken).ConfigureAwait(false);
            LastWords = [flag ? (ushort)1 : (ushort)0];
            return flag ? "1" : "0";
        }

        ushort[] words = await Unit.ReadWordsAsync(Address.AsWord(), Words, cancellationToken).ConfigureAwait(false);
        string text = PollValueTypes.Format(Type, Address, Count, words, WordOrder);
        LastWords = words;
        return text;
    }

    /// <summary>The outcome for a tag sink: the last value read when <paramref name="quality"/> is good.</summary>
    public TagChange Change(string link, TagQuality quality, DateTimeOffset time, string? error = null)
        => new(link, UnitNumber, Name, AddressText, Type, quality == TagQuality.Good ? TagValueCodec.Decode(Type, Address, Count, LastWords, WordOrder) : null, quality, time, error);
}
