using System.Globalization;

namespace OmronHostLink;

/// <summary>
/// One contiguous range of words (or timer/counter numbers) a PLC model has in one area, whether a host may write it,
/// and the manual page that says so.
/// </summary>
public sealed class PlcAreaRange
{
    internal PlcAreaRange(PlcArea area, int first, int last, bool writable, string source, bool verified, int bankCount = 0)
    {
        Area = area;
        First = first;
        Last = last;
        Writable = writable;
        Source = source;
        Verified = verified;
        BankCount = bankCount;
    }

    /// <summary>The area.</summary>
    public PlcArea Area { get; }

    /// <summary>The first word (or timer/counter number) of the range.</summary>
    public int First { get; }

    /// <summary>The last word (or timer/counter number) of the range, inclusive.</summary>
    public int Last { get; }

    /// <summary>Whether a host may write the range (false: the PLC refuses, or ignores, writes there).</summary>
    public bool Writable { get; }

    /// <summary>For <see cref="PlcArea.Em"/>, the number of banks (0 to <see cref="BankCount"/> − 1) the range exists in; 0 otherwise.</summary>
    public int BankCount { get; }

    /// <summary>The manual and page the range comes from, or why it is not verified.</summary>
    public string Source { get; }

    /// <summary>Whether a manual page was found for the range; false where the range is the best available knowledge only.</summary>
    public bool Verified { get; }

    /// <summary>Whether <paramref name="word"/> (in <paramref name="bank"/>) lies in the range.</summary>
    /// <param name="word">The word or timer/counter number.</param>
    /// <param name="bank">The EM bank; 0 for other areas.</param>
    /// <returns>True when the word is in the range.</returns>
    public bool Contains(int word, int bank = 0) =>
        word >= First && word <= Last && (Area != PlcArea.Em || (uint)bank < (uint)BankCount);

    /// <summary>The range as a user writes it: <c>D0–D2047</c>, <c>E0_0–E0_6143</c> (banks 0–2).</summary>
    /// <returns>The text.</returns>
    public override string ToString()
    {
        var text = $"{PlcAreaInfo.Format(Area, First, -1, 0)}–{PlcAreaInfo.Format(Area, Last, -1, 0)}";
        return Area == PlcArea.Em && BankCount > 1
            ? text + " (banks 0–" + (BankCount - 1).ToString("X", CultureInfo.InvariantCulture) + ")"
            : text;
    }
}
