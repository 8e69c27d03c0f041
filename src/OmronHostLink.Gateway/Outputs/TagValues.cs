namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// A tag's words as the values outputs carry (<see cref="TagChange.Value"/>): decoded by the core's
/// <see cref="PlcValueCodec"/>, one value as a scalar and several as an array of their .NET type
/// (<see cref="PlcValue.ToObject"/>), a timer or counter completion flag as a bool.
/// </summary>
internal static class TagValues
{
    /// <summary>Decodes the words of a successful read.</summary>
    /// <param name="type">How the words are read.</param>
    /// <param name="address">The first address (its bit number for <c>bit</c>).</param>
    /// <param name="count">How many values (characters for <c>string</c>, bits for <c>bit</c>).</param>
    /// <param name="words">The words read; a timer/counter completion flag is one word, 0 or 1.</param>
    /// <param name="order">Word order of 32- and 64-bit values.</param>
    /// <exception cref="FormatException">A BCD word holds a nibble above 9, or text bytes are not ASCII.</exception>
    public static object Decode(PlcValueType type, PlcAddress address, int count, ReadOnlySpan<ushort> words, WordOrder order)
    {
        if (type == PlcValueType.Bit && address.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return words[0] != 0;
        }

        PlcValue[] values = PlcValueCodec.DecodeValues(type, words, count, order, Math.Max(address.Bit, 0));
        if (values.Length == 1)
        {
            return values[0].ToObject();
        }

        Type elementType = values[0].ToObject().GetType();
        var array = Array.CreateInstance(elementType, values.Length);
        for (int i = 0; i < values.Length; i++)
        {
            array.SetValue(values[i].ToObject(), i);
        }

        return array;
    }
}
