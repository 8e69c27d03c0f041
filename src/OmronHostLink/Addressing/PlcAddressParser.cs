namespace OmronHostLink;

/// <summary>
/// Reads CX-Programmer address spellings. Grammar (case-insensitive, surrounding whitespace trimmed):
/// <c>[prefix [spaces]] [bank '_'] word ['.' bit]</c>, where EM alone has the hex bank digit.
/// </summary>
internal static class PlcAddressParser
{
    // Longest prefixes first, so that "CIO" is not read as counter "C" + "IO" and "DM" not as "D" + "M".
    private static readonly (string Prefix, PlcArea Area)[] Prefixes =
    [
        ("CIO", PlcArea.Cio),
        ("CNT", PlcArea.Counter),
        ("TIM", PlcArea.Timer),
        ("DM", PlcArea.Dm),
        ("WR", PlcArea.Work),
        ("HR", PlcArea.Holding),
        ("AR", PlcArea.Auxiliary),
        ("EM", PlcArea.Em),

        // C200H/CQM1/CPM-era names: IR and SR words are CIO words (read with RR), LR is its own area (RL), and "TC" is the
        // shared timer/counter number space of those PLCs, read as a present value with RC like a timer.
        ("IR", PlcArea.Cio),
        ("SR", PlcArea.Cio),
        ("LR", PlcArea.Link),
        ("TC", PlcArea.Timer),
        ("D", PlcArea.Dm),
        ("W", PlcArea.Work),
        ("H", PlcArea.Holding),
        ("A", PlcArea.Auxiliary),
        ("T", PlcArea.Timer),
        ("C", PlcArea.Counter),
        ("E", PlcArea.Em),
    ];

    // Enough digits for any real word number; longer runs are reported as too large rather than overflowing.
    private const int MaxDigits = 9;

    public static bool TryParse(ReadOnlySpan<char> text, out PlcAddress address, out string? error)
    {
        address = default;

        // Only spaces and tabs count as whitespace here: a CR, LF, NUL or other control character is refused, not
        // trimmed (the bad-input table found "D1\r" accepted); it is a line ending or garbage, never part of an address.
        for (var k = 0; k < text.Length; k++)
        {
            if (char.IsControl(text[k]) && text[k] != '\t')
            {
                error = $"it contains the control character U+{(int)text[k]:X4} at position {k}";
                return false;
            }
        }

        var s = text.Trim();
        if (s.IsEmpty)
        {
            error = "the text is empty";
            return false;
        }

        var i = 0;
        var area = PlcArea.Cio;
        if (!IsDigit(s[0]))
        {
            if (!TryMatchPrefix(s, out area, out i))
            {
                error = $"unknown area '{LeadingLetters(s)}'; expected CIO, W, H, A, D, T, C or E<bank>_ followed by a word number (or, for C-series PLCs, IR, SR, LR, HR, AR, DM, TC)";
                return false;
            }

            while (i < s.Length && char.IsWhiteSpace(s[i]))
            {
                i++;
            }
        }

        var bank = 0;
        if (area == PlcArea.Em && !TryReadBank(s, ref i, out bank, out error))
        {
            return false;
        }

        var digitsStart = i;
        if (!TryReadNumber(s, ref i, out var word))
        {
            error = i < s.Length
                ? $"expected a word number after '{s.Slice(0, i).ToString()}' but found '{s.Slice(i).ToString()}'"
                : $"the word number after '{s.Slice(0, i).ToString()}' is missing";
            return false;
        }

        if (word >= PlcAreaInfo.Size(area))
        {
            error = $"word {s.Slice(digitsStart, i - digitsStart).ToString()} is outside the {PlcAreaInfo.Extent(area, bank)}";
            return false;
        }

        var bit = -1;
        if (i < s.Length && s[i] == '.')
        {
            i++;
            if (!PlcAreaInfo.AllowsBit(area))
            {
                error = "a timer or counter address names a T/C number and cannot take a bit";
                return false;
            }

            var bitStart = i;
            if (!TryReadNumber(s, ref i, out bit))
            {
                error = "the bit number after '.' is missing";
                return false;
            }

            if (i - bitStart > 2 || bit > 15)
            {
                error = $"bit '{s.Slice(bitStart, i - bitStart).ToString()}' is not a bit number; bits are 00–15";
                return false;
            }
        }

        if (i < s.Length)
        {
            error = $"unexpected '{s.Slice(i).ToString()}' after '{s.Slice(0, i).ToString()}'";
            return false;
        }

        address = new PlcAddress(area, word, bit, bank);
        error = null;
        return true;
    }

    private static bool TryMatchPrefix(ReadOnlySpan<char> s, out PlcArea area, out int length)
    {
        foreach (var (prefix, candidate) in Prefixes)
        {
            if (StartsWithIgnoreCase(s, prefix))
            {
                area = candidate;
                length = prefix.Length;
                return true;
            }
        }

        area = default;
        length = 0;
        return false;
    }

    // EM bank: one hex digit 0–C, then '_' (E1_100). Without a bank the address would mean the "current bank", which we do not support.
    private static bool TryReadBank(ReadOnlySpan<char> s, ref int i, out int bank, out string? error)
    {
        bank = 0;
        if (s.Slice(i).IndexOf('_') < 0)
        {
            error = "an EM address needs a bank: write E<bank>_<word>, e.g. E0_100 (banks 0–C)";
            return false;
        }

        if (s[i] == '_')
        {
            error = "the EM bank is missing before '_'; write E<bank>_<word> with bank 0–C";
            return false;
        }

        if (i + 1 >= s.Length || s[i + 1] != '_' || !TryHexDigit(s[i], out bank))
        {
            var bankText = s.Slice(i, s.Slice(i).IndexOf('_')).ToString();
            error = $"EM bank '{bankText}' is not a hex digit 0–C";
            return false;
        }

        if (bank >= PlcAreaInfo.EmBankCount)
        {
            error = $"EM bank {char.ToUpperInvariant(s[i])} does not exist on CS/CJ; banks are 0–C";
            return false;
        }

        i += 2;
        error = null;
        return true;
    }

    private static bool TryReadNumber(ReadOnlySpan<char> s, ref int i, out int value)
    {
        var start = i;
        value = 0;
        while (i < s.Length && IsDigit(s[i]))
        {
            // Past MaxDigits the value only needs to be "too large"; saturate instead of overflowing.
            value = i - start < MaxDigits ? (value * 10) + (s[i] - '0') : int.MaxValue;
            i++;
        }

        return i > start;
    }

    private static bool StartsWithIgnoreCase(ReadOnlySpan<char> s, string prefix)
    {
        if (s.Length < prefix.Length)
        {
            return false;
        }

        for (var k = 0; k < prefix.Length; k++)
        {
            if (char.ToUpperInvariant(s[k]) != prefix[k])
            {
                return false;
            }
        }

        return true;
    }

    private static string LeadingLetters(ReadOnlySpan<char> s)
    {
        var n = 0;
        while (n < s.Length && char.IsLetter(s[n]))
        {
            n++;
        }

        return n == 0 ? s.Slice(0, 1).ToString() : s.Slice(0, n).ToString();
    }

    private static bool TryHexDigit(char c, out int value)
    {
        value = c switch
        {
            >= '0' and <= '9' => c - '0',
            >= 'A' and <= 'F' => c - 'A' + 10,
            >= 'a' and <= 'f' => c - 'a' + 10,
            _ => -1,
        };
        return value >= 0;
    }

    // char.IsDigit accepts other scripts' digits; addresses are ASCII.
    private static bool IsDigit(char c) => c is >= '0' and <= '9';
}
