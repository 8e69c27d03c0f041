using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>A watched tag's value changed, or was read for the first time (<see cref="IsInitial"/>).</summary>
public sealed class TagValueChangedEventArgs : EventArgs
{
    /// <summary>Creates the event's data.</summary>
    /// <param name="tagText">The tag as it was given (<c>D100:float</c>).</param>
    /// <param name="tag">The tag.</param>
    /// <param name="index">The tag's position in the watched list.</param>
    /// <param name="oldValue">The value reported before; null on the first report.</param>
    /// <param name="newValue">The value read.</param>
    /// <param name="timestamp">When the read completed.</param>
    public TagValueChangedEventArgs(string tagText, PlcTag tag, int index, PlcValue? oldValue, PlcValue newValue, DateTimeOffset timestamp)
    {
        TagText = Guard.NotNull(tagText);
        Tag = Guard.NotNull(tag);
        Index = index;
        OldValue = oldValue;
        NewValue = newValue;
        Timestamp = timestamp;
    }

    /// <summary>The tag as it was given to the watcher: <c>D100:float</c>, <c>CIO 10.03</c>.</summary>
    public string TagText { get; }

    /// <summary>The tag: address, type and unit.</summary>
    public PlcTag Tag { get; }

    /// <summary>The tag's position in the watched list.</summary>
    public int Index { get; }

    /// <summary>The value reported before; null the first time the tag is reported.</summary>
    public PlcValue? OldValue { get; }

    /// <summary>The value read, in the tag's type (<c>NewValue.ToString()</c> for a label, <c>ToSingle()</c> and the like for a number).</summary>
    public PlcValue NewValue { get; }

    /// <summary>When the read that saw the value completed.</summary>
    public DateTimeOffset Timestamp { get; }

    /// <summary>Whether this is the tag's first report (no old value): the first successful read after Start.</summary>
    public bool IsInitial => OldValue is null;
}
