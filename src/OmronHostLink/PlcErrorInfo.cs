namespace OmronHostLink;

/// <summary>
/// What MF (ERROR READ) reports: two words of error information. Their bits are model-specific (see the CPU Unit's
/// operation manual); <see cref="ActiveBits"/> lists which are on.
/// </summary>
public sealed class PlcErrorInfo
{
    /// <summary>Creates the error information.</summary>
    public PlcErrorInfo(ushort firstWord, ushort secondWord)
    {
        FirstWord = firstWord;
        SecondWord = secondWord;
    }

    /// <summary>The first word of error information.</summary>
    public ushort FirstWord { get; }

    /// <summary>The second word of error information.</summary>
    public ushort SecondWord { get; }

    /// <summary>True when any error bit is on.</summary>
    public bool HasErrors => FirstWord != 0 || SecondWord != 0;

    /// <summary>The bits that are on, as (word 1 or 2, bit 0-15).</summary>
    public IReadOnlyList<(int Word, int Bit)> ActiveBits
    {
        get
        {
            var bits = new List<(int, int)>();
            for (int b = 15; b >= 0; b--)
            {
                if ((FirstWord & (1 << b)) != 0)
                {
                    bits.Add((1, b));
                }
            }

            for (int b = 15; b >= 0; b--)
            {
                if ((SecondWord & (1 << b)) != 0)
                {
                    bits.Add((2, b));
                }
            }

            return bits;
        }
    }

    /// <inheritdoc/>
    public override string ToString()
        => HasErrors
            ? $"errors {FirstWord:X4} {SecondWord:X4} (bits on: {string.Join(", ", ActiveBits.Select(b => $"word {b.Word} bit {b.Bit:D2}"))})"
            : "no errors";
}
