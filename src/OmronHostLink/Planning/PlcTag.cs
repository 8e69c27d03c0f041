namespace OmronHostLink.Planning;

/// <summary>
/// A value to read: an address, how to read it, and optionally the unit (multidrop) it lives in. Used with
/// <see cref="ReadPlanner"/> and <c>ReadTagsAsync</c>.
/// </summary>
public sealed class PlcTag
{
    /// <summary>Creates a tag from an address string.</summary>
    /// <param name="address">The address, e.g. <c>D100</c> or <c>CIO10.03</c>.</param>
    /// <param name="type">How the words are read.</param>
    /// <param name="unit">The unit number 0-31, or null for the unit of the client (or view) that reads it.</param>
    /// <exception cref="FormatException">The address is not valid.</exception>
    /// <exception cref="ArgumentException">The type does not fit the address (a bit type needs a bit address, a word type a word address).</exception>
    public PlcTag(string address, PlcValueType type = PlcValueType.Word, int? unit = null)
        : this(PlcAddress.Parse(address), type, unit)
    {
    }

    /// <summary>Creates a tag. A <see cref="PlcValueType.Bit"/> tag on a timer or counter number (<c>T5</c>, <c>C7</c>) is its completion flag.</summary>
    /// <param name="address">The address.</param>
    /// <param name="type">How the words are read.</param>
    /// <param name="unit">The unit number 0-31, or null for the unit of the client (or view) that reads it.</param>
    /// <exception cref="ArgumentException">The type does not fit the address, or the words run past the end of the area.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31.</exception>
    public PlcTag(PlcAddress address, PlcValueType type = PlcValueType.Word, int? unit = null)
    {
        if (!Enum.IsDefined(typeof(PlcValueType), type))
        {
            throw new ArgumentOutOfRangeException(nameof(type), type, "Unknown tag type.");
        }

        if (type == PlcValueType.String)
        {
            throw new ArgumentException("A tag holds one value of a fixed size; read text with ReadStringAsync, which takes its length.", nameof(type));
        }

        if (type == PlcValueType.Bit && !address.IsBit && !IsTimerOrCounter(address))
        {
            throw new ArgumentException($"{address} names a word; a Bit tag needs a bit address such as {address.AsWord()}.00, or a timer/counter number for its completion flag.", nameof(type));
        }

        if (type != PlcValueType.Bit && address.IsBit)
        {
            throw new ArgumentException($"{address} names a bit; a {type} tag needs a word address.", nameof(type));
        }

        if (unit is { } u)
        {
            Guard.Unit(u);
        }

        WordCount = PlcValueCodec.WordCount(type);
        if ((long)address.Word + WordCount > PlcAddress.AreaSize(address.Area))
        {
            throw new ArgumentException($"A {type} at {address} runs past the end of the area.", nameof(address));
        }

        Address = address;
        Type = type;
        Unit = unit;
    }

    /// <summary>
    /// Parses tag text: an address, optionally followed by a colon and a type name — <c>D100</c> (a word),
    /// <c>D100:float</c>, <c>E1_200:int32</c>, <c>CIO10.03</c> (a bit address is a bit), <c>D20:bcd32</c>,
    /// <c>T5:bit</c> (a timer's completion flag; <c>T5</c> alone is its present value). Type names
    /// are <see cref="PlcValueTypes.Names"/> but <c>string</c>, in any case; spaces around the parts are ignored.
    /// </summary>
    /// <remarks>
    /// A tag is one value, so the text has no count (<c>D100:float[4]</c> is refused): read a run of values with
    /// <c>ReadAsync&lt;T&gt;(address, count)</c>, or list one tag a value. The unit is not part of the text: pass it, or read
    /// from the unit's view.
    /// </remarks>
    /// <param name="text">The tag text.</param>
    /// <param name="unit">The unit number 0-31, or null for the unit of the client (or view) that reads it.</param>
    /// <returns>The tag.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is null.</exception>
    /// <exception cref="FormatException">The text is not a tag; the message says why and shows the form.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The unit is not 0-31.</exception>
    public static PlcTag Parse(string text, int? unit = null)
    {
        Guard.NotNull(text);
        int colon = text.IndexOf(':');
        string addressText = (colon < 0 ? text : text.Substring(0, colon)).Trim();
        string? typeText = colon < 0 ? null : text.Substring(colon + 1).Trim();
        if (addressText.Length == 0)
        {
            throw new FormatException($"'{text}' is not a tag: it has no address. A tag is an address with an optional type, as in D100 or D100:float.");
        }

        PlcAddress address;
        try
        {
            address = PlcAddress.Parse(addressText);
        }
        catch (FormatException e)
        {
            throw new FormatException($"'{text}' is not a tag: {e.Message}", e);
        }

        PlcValueType type = address.IsBit ? PlcValueType.Bit : PlcValueType.Word;
        if (typeText is not null)
        {
            if (typeText.IndexOf('[') >= 0)
            {
                throw new FormatException($"'{text}' is not a tag: a tag is one value and takes no count; read several with ReadAsync<T>(address, count) or list one tag a value.");
            }

            if (!PlcValueTypes.TryParse(typeText, out type) || type == PlcValueType.String)
            {
                throw new FormatException($"'{text}' is not a tag: '{typeText}' is not a tag type; use one of {string.Join(", ", PlcValueTypes.Names.Where(n => n != PlcValueType.String.Name()))}, as in D100:float.");
            }
        }

        if (type == PlcValueType.Bit != address.IsBit && !(type == PlcValueType.Bit && IsTimerOrCounter(address)))
        {
            throw new FormatException(type == PlcValueType.Bit
                ? $"'{text}' is not a tag: a bit tag needs a bit address such as {address}.00."
                : $"'{text}' is not a tag: {address} names a bit, and a {type.Name()} tag needs a word address such as {address.AsWord()}.");
        }

        if ((long)address.Word + PlcValueCodec.WordCount(type) > PlcAddress.AreaSize(address.Area))
        {
            throw new FormatException($"'{text}' is not a tag: a {type.Name()} at {address} runs past the end of the area.");
        }

        return new PlcTag(address, type, unit);
    }

    /// <summary>The address (for <see cref="PlcValueType.Bit"/>, a bit address).</summary>
    public PlcAddress Address { get; }

    /// <summary>How the words are read.</summary>
    public PlcValueType Type { get; }

    /// <summary>The unit, or null for the reading client's own unit.</summary>
    public int? Unit { get; }

    /// <summary>The number of words the value occupies (1, 2 or 4; 1 for a completion flag).</summary>
    public int WordCount { get; }

    /// <summary>Whether the tag is a timer's or counter's completion flag (a <see cref="PlcValueType.Bit"/> tag on <c>T5</c> or <c>C7</c>).</summary>
    public bool IsCompletionFlag => Type == PlcValueType.Bit && !Address.IsBit;

    /// <inheritdoc/>
    public override string ToString() => Unit is { } u ? $"{u:D2}:{Address} ({Type})" : $"{Address} ({Type})";

    private static bool IsTimerOrCounter(PlcAddress address) => address.Area is PlcArea.Timer or PlcArea.Counter;
}

/// <summary>The value read for one <see cref="PlcTag"/>.</summary>
public readonly struct PlcTagValue
{
    /// <summary>Creates a value.</summary>
    public PlcTagValue(PlcTag tag, ushort[] words, object value)
    {
        Tag = tag;
        Words = words;
        Value = value;
    }

    /// <summary>The tag.</summary>
    public PlcTag Tag { get; }

    /// <summary>
    /// The raw words (one, two or four), as read. A bit tag that a plan read as a bit alone (a QQ bit item) has its word
    /// as far as it was read: the tag's bit, the others 0.
    /// </summary>
    public IReadOnlyList<ushort> Words { get; }

    /// <summary>
    /// The value in the tag's type, as <see cref="PlcValue.ToObject"/> gives it: <see cref="ushort"/> (Word, UInt16),
    /// <see cref="short"/> (Int16), <see cref="int"/> (Int32, Bcd, Bcd32), <see cref="uint"/> (UInt32), <see cref="float"/>
    /// (Float), <see cref="double"/> (Double) or <see cref="bool"/> (Bit).
    /// </summary>
    public object Value { get; }

    /// <inheritdoc/>
    public override string ToString() => $"{Tag} = {Value}";
}
