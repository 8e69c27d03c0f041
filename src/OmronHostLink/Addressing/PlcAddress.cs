using System.Diagnostics.CodeAnalysis;

namespace OmronHostLink;

/// <summary>
/// A word or bit address in a CS/CJ-series PLC, such as <c>D100</c>, <c>CIO100.05</c> or <c>E1_100</c>.
/// </summary>
/// <remarks>
/// An address is always within its area's size: every way to make one validates it.
/// <c>default(PlcAddress)</c> is <c>CIO0</c>.
/// </remarks>
public readonly struct PlcAddress : IEquatable<PlcAddress>
{
    // Compact storage; the bit is kept as bit + 1 so that default(PlcAddress) is a word address (CIO0), not CIO0.00.
    private readonly ushort _word;
    private readonly sbyte _bitPlusOne;
    private readonly byte _bank;
    private readonly PlcArea _area;

    // Callers have validated the parts.
    internal PlcAddress(PlcArea area, int word, int bit, int bank)
    {
        _area = area;
        _word = (ushort)word;
        _bitPlusOne = (sbyte)(bit + 1);
        _bank = (byte)bank;
    }

    /// <summary>The memory area.</summary>
    public PlcArea Area => _area;

    /// <summary>The word number; for <see cref="PlcArea.Timer"/> and <see cref="PlcArea.Counter"/> the T/C number.</summary>
    public int Word => _word;

    /// <summary>The bit number 0–15 for a bit address; -1 when the address names a whole word.</summary>
    public int Bit => _bitPlusOne - 1;

    /// <summary>Whether the address names a single bit (<c>CIO100.05</c>) rather than a word.</summary>
    public bool IsBit => _bitPlusOne != 0;

    /// <summary>The EM bank 0–12 (0x0–0xC) when <see cref="Area"/> is <see cref="PlcArea.Em"/>; 0 otherwise.</summary>
    public int Bank => _bank;

    /// <summary>The number of words (or T/C numbers) in <paramref name="area"/> on a CS/CJ CPU; for EM, per bank.</summary>
    /// <param name="area">The memory area.</param>
    /// <returns>6144 for CIO, 512 for W and H, 960 for A, 32768 for D and each EM bank, 4096 for T and C.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="area"/> is not a defined <see cref="PlcArea"/>.</exception>
    public static int AreaSize(PlcArea area) => PlcAreaInfo.Size(area);

    /// <summary>Makes a word address, checked against the area's size.</summary>
    /// <param name="area">The memory area.</param>
    /// <param name="word">The word (or T/C) number, from 0.</param>
    /// <param name="bank">The EM bank 0–12 for <see cref="PlcArea.Em"/>; must be 0 for other areas.</param>
    /// <returns>The address.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The area, word or bank is out of range.</exception>
    public static PlcAddress WordOf(PlcArea area, int word, int bank = 0)
    {
        CheckWord(area, word, bank);
        return new PlcAddress(area, word, -1, bank);
    }

    /// <summary>Makes a bit address, checked against the area's size.</summary>
    /// <param name="area">The memory area; not <see cref="PlcArea.Timer"/> or <see cref="PlcArea.Counter"/>.</param>
    /// <param name="word">The word number, from 0.</param>
    /// <param name="bit">The bit number 0–15.</param>
    /// <param name="bank">The EM bank 0–12 for <see cref="PlcArea.Em"/>; must be 0 for other areas.</param>
    /// <returns>The address.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The area, word, bit or bank is out of range.</exception>
    /// <exception cref="ArgumentException"><paramref name="area"/> is a timer or counter area, which has no bits.</exception>
    public static PlcAddress BitOf(PlcArea area, int word, int bit, int bank = 0)
    {
        CheckWord(area, word, bank);
        CheckBit(area, bit);
        return new PlcAddress(area, word, bit, bank);
    }

    /// <summary>Parses an address written the CX-Programmer way.</summary>
    /// <param name="text">
    /// The address, case-insensitive, surrounding whitespace ignored: <c>D100</c>, <c>DM100</c>, <c>D 100</c>,
    /// <c>CIO100</c>, <c>100</c>, <c>CIO100.05</c>, <c>100.5</c>, <c>W30</c>, <c>WR30.06</c>, <c>H10</c>, <c>HR10.03</c>,
    /// <c>A448</c>, <c>AR448.01</c>, <c>T5</c>, <c>TIM5</c>, <c>C7</c>, <c>CNT7</c>, <c>E1_100</c>, <c>EM1_100</c>, <c>EC_100.03</c>.
    /// </param>
    /// <returns>The address.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is <see langword="null"/>.</exception>
    /// <exception cref="FormatException">The text is not an address, or names a word outside its area; the message says why.</exception>
    public static PlcAddress Parse(string text)
    {
        Guard.NotNull(text);
        if (!PlcAddressParser.TryParse(text.AsSpan(), out var address, out var error))
        {
            throw new FormatException($"'{text}' is not a valid PLC address: {error}.");
        }

        return address;
    }

    /// <summary>Parses an address as <see cref="Parse(string)"/> does, without throwing.</summary>
    /// <param name="text">The address text; <see langword="null"/> gives <see langword="false"/>.</param>
    /// <param name="address">The address when the result is <see langword="true"/>; otherwise <c>default</c>.</param>
    /// <returns>Whether <paramref name="text"/> is a valid address.</returns>
    public static bool TryParse([NotNullWhen(true)] string? text, out PlcAddress address)
    {
        if (text is null)
        {
            address = default;
            return false;
        }

        return PlcAddressParser.TryParse(text.AsSpan(), out address, out _);
    }

    /// <summary>The same word with a bit number: <c>D100</c> → <c>D100.05</c>.</summary>
    /// <param name="bit">The bit number 0–15.</param>
    /// <returns>The bit address.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="bit"/> is not 0–15.</exception>
    /// <exception cref="ArgumentException">The address is a timer or counter, which has no bits.</exception>
    public PlcAddress WithBit(int bit)
    {
        CheckBit(_area, bit);
        return new PlcAddress(_area, _word, bit, _bank);
    }

    /// <summary>The word that holds this address: <c>CIO100.05</c> → <c>CIO100</c>; a word address is returned unchanged.</summary>
    /// <returns>The word address.</returns>
    public PlcAddress AsWord() => new(_area, _word, -1, _bank);

    /// <summary>The address <paramref name="words"/> words further on (or back), keeping the bit number: <c>D100.05</c> + 2 → <c>D102.05</c>.</summary>
    /// <param name="words">The number of words to move; may be negative.</param>
    /// <returns>The moved address.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The result would fall outside the area (or the EM bank).</exception>
    public PlcAddress Offset(int words)
    {
        var target = (long)_word + words;
        if (target < 0 || target >= PlcAreaInfo.Size(_area))
        {
            throw new ArgumentOutOfRangeException(
                nameof(words),
                words,
                $"{this} offset by {words} words falls outside the {PlcAreaInfo.Extent(_area, _bank)}.");
        }

        return new PlcAddress(_area, (int)target, Bit, _bank);
    }

    /// <summary>
    /// Checks that <paramref name="count"/> words starting at this address can be transferred with <paramref name="commandSet"/>.
    /// </summary>
    /// <param name="count">The number of words (T/C present values for timers and counters), at least 1. For a bit address
    /// this still counts words, starting with the word that holds the bit.</param>
    /// <param name="commandSet">The command set: C-mode reaches less of the PLC than FINS.</param>
    /// <param name="forWrite">Whether the transfer writes to the PLC (A0–A447 are read-only).</param>
    /// <exception cref="ArgumentOutOfRangeException">
    /// <paramref name="count"/> is less than 1; the words run past the end of the area; or, with C-mode, they go beyond
    /// what C-mode reaches (D/EM 10000 and above, T/C 2048 and above).
    /// </exception>
    /// <exception cref="ArgumentException">The transfer writes to the read-only auxiliary words A0–A447, or uses C-mode on the work area.</exception>
    public void EnsureRange(int count, HostLinkCommandSet commandSet, bool forWrite) =>
        AddressRangeCheck.Ensure(this, count, commandSet, forWrite);

    /// <summary>The canonical spelling: <c>D100</c>, <c>CIO100.05</c>, <c>W30</c>, <c>H10.03</c>, <c>A448</c>, <c>T5</c>, <c>C7</c>, <c>E1_100.02</c>.</summary>
    /// <returns>Text that <see cref="Parse(string)"/> reads back to the same address.</returns>
    public override string ToString() => PlcAreaInfo.Format(_area, _word, Bit, _bank);

    /// <summary>Whether two addresses name the same word or bit.</summary>
    /// <param name="other">The other address.</param>
    /// <returns><see langword="true"/> when area, bank, word and bit are all equal.</returns>
    public bool Equals(PlcAddress other) =>
        _area == other._area && _word == other._word && _bitPlusOne == other._bitPlusOne && _bank == other._bank;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is PlcAddress other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => ((int)_area << 28) ^ (_bank << 23) ^ ((_bitPlusOne & 0x1F) << 16) ^ _word;

    /// <summary>Whether two addresses name the same word or bit.</summary>
    /// <param name="left">The first address.</param>
    /// <param name="right">The second address.</param>
    /// <returns><see langword="true"/> when they are equal.</returns>
    public static bool operator ==(PlcAddress left, PlcAddress right) => left.Equals(right);

    /// <summary>Whether two addresses differ.</summary>
    /// <param name="left">The first address.</param>
    /// <param name="right">The second address.</param>
    /// <returns><see langword="true"/> when they are not equal.</returns>
    public static bool operator !=(PlcAddress left, PlcAddress right) => !left.Equals(right);

    private static void CheckWord(PlcArea area, int word, int bank)
    {
        if (!PlcAreaInfo.IsDefined(area))
        {
            throw new ArgumentOutOfRangeException(nameof(area), area, $"{area} is not a PLC area.");
        }

        if (area == PlcArea.Em)
        {
            if ((uint)bank >= PlcAreaInfo.EmBankCount)
            {
                throw new ArgumentOutOfRangeException(nameof(bank), bank, $"EM bank {bank} does not exist on CS/CJ; banks are 0–12 (0x0–0xC).");
            }
        }
        else if (bank != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(bank), bank, $"A bank applies only to the EM area, not the {PlcAreaInfo.Name(area)}; it must be 0.");
        }

        if ((uint)word >= (uint)PlcAreaInfo.Size(area))
        {
            throw new ArgumentOutOfRangeException(nameof(word), word, $"Word {word} is outside the {PlcAreaInfo.Extent(area, bank)}.");
        }
    }

    private static void CheckBit(PlcArea area, int bit)
    {
        if (!PlcAreaInfo.AllowsBit(area))
        {
            throw new ArgumentException($"The {PlcAreaInfo.Name(area)} has no bit addresses: a timer or counter number cannot take a bit.", nameof(bit));
        }

        if ((uint)bit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, $"Bit {bit} does not exist; bits are 0–15.");
        }
    }
}
