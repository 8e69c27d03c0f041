using OmronHostLink.Planning;

namespace OmronHostLink.Cli;

/// <summary>
/// The values of a <see cref="ReadRequest"/> as a watch sees them (<c>monitor</c>): the tags to watch, and the snapshot
/// that the watch's changes keep current, with the values that changed in the poll under way.
/// </summary>
/// <remarks>
/// Each value is one tag of the request's type: a number, a bit of a run of bits, a timer/counter completion flag.
/// BCD and text are watched as their words instead: their words may hold no value of the type (<c>not BCD</c>,
/// <c>not ASCII text</c>), which the console shows like any value, while the watch counts a tag that does not decode as
/// a failed poll. Their values are decoded from the words by the codec, as <c>read</c> does; a text is one value over
/// all its words, so any word that changes changes it.
/// </remarks>
internal sealed class WatchedValues
{
    private readonly ReadRequest _request;
    private readonly int[] _valueOf;
    private readonly int[] _firstWord;
    private readonly bool _decodedFromWords;
    private readonly SortedSet<int> _changed = [];

    public WatchedValues(ReadRequest request)
    {
        _request = request;
        _decodedFromWords = request.Kind is PlcValueType.Bcd or PlcValueType.String;
        int values = request.Kind == PlcValueType.String ? 1 : request.Count;

        // Bits and flags are shown by value alone; words are kept for the types shown with their words.
        Current = new Snapshot(request, request.Kind == PlcValueType.Bit ? [] : new ushort[request.Words], new PlcValue?[values]);
        int tags = _decodedFromWords ? request.Words : values;
        var list = new PlcTag[tags];
        _valueOf = new int[tags];
        _firstWord = new int[tags];
        for (int t = 0; t < tags; t++)
        {
            if (_decodedFromWords)
            {
                list[t] = new PlcTag(request.Address.Offset(t), PlcValueType.Word);
                _valueOf[t] = request.Kind == PlcValueType.String ? 0 : t;
                _firstWord[t] = t;
            }
            else
            {
                list[t] = new PlcTag(Current.AddressOf(t), request.Kind);
                _valueOf[t] = t;
                _firstWord[t] = request.Kind == PlcValueType.Bit ? -1 : t * request.Kind.WordsPerValue();
            }
        }

        Tags = list;
    }

    /// <summary>The tags to watch, in the order of the watch's <see cref="WatchEvent.TagIndex"/>.</summary>
    public IReadOnlyList<PlcTag> Tags { get; }

    /// <summary>The values as of the last poll.</summary>
    public Snapshot Current { get; }

    /// <summary>Takes a <see cref="WatchEventKind.Changed"/> event of the poll under way.</summary>
    public void Apply(WatchEvent change)
    {
        int t = change.TagIndex;
        if (_firstWord[t] >= 0)
        {
            for (int i = 0; i < change.Words.Count; i++)
            {
                Current.Words[_firstWord[t] + i] = change.Words[i];
            }
        }

        if (!_decodedFromWords)
        {
            Current.Values[_valueOf[t]] = change.NewValue;
        }

        _changed.Add(_valueOf[t]);
    }

    /// <summary>Ends the poll under way: the values that changed in it (all on the first), in address order.</summary>
    public List<int> EndPoll()
    {
        if (_decodedFromWords && _changed.Count > 0)
        {
            _request.Decode(Current.Words).CopyTo(Current.Values, 0);
        }

        var changed = _changed.ToList();
        _changed.Clear();
        return changed;
    }
}
