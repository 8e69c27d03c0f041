namespace OmronHostLink;

/// <summary>
/// Converts between PLC words (16-bit, as read and written) and .NET values: BCD, 32-bit integers, REAL, ASCII text and bits.
/// </summary>
/// <remarks>Span overloads allocate nothing; they read or write only the words they need at the start of the span.</remarks>
public static partial class PlcWords
{
    private static void EnsureLength(int length, int needed, string name)
    {
        if (length < needed)
        {
            throw new ArgumentException($"{needed} words are needed but the span holds {length}.", name);
        }
    }

    private static void CheckOrder(WordOrder order)
    {
        if (order is not (WordOrder.LowWordFirst or WordOrder.HighWordFirst))
        {
            throw new ArgumentOutOfRangeException(nameof(order), order, $"{order} is not a word order.");
        }
    }
}
