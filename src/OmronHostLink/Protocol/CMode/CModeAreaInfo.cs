namespace OmronHostLink.Protocol.CMode;

/// <summary>Headers and address limits of each <see cref="CModeArea"/> on CS/CJ CPU Units (W342 4-3; PROTOCOL.md §3).</summary>
internal static class CModeAreaInfo
{
    /// <summary>The highest EM bank C-mode reaches (bank C).</summary>
    public const int MaxEmBank = PlcAreaInfo.EmBankCount - 1;

    /// <summary>
    /// Where counters start among the timer/counter entries of RC, WC and RG: timer <c>n</c> is entry <c>n</c>, counter
    /// <c>n</c> is entry 2048 + <c>n</c>; so C-mode reaches timers and counters 0–2047 (W342 p128).
    /// </summary>
    public const int CounterOffset = 2048;

    /// <summary>The CIO word the LR area starts at on CS/CJ: LR <c>n</c> (RL, WL) is CIO 1000 + <c>n</c>.</summary>
    public const int LrCioStart = 1000;

    /// <summary>The read header (RR, RL, RH, RC, RG, RD, RJ, RE).</summary>
    public static string ReadHeader(CModeArea area) => area switch
    {
        CModeArea.Cio => "RR",
        CModeArea.Lr => "RL",
        CModeArea.Holding => "RH",
        CModeArea.TimerCounterPv => "RC",
        CModeArea.TimerCounterStatus => "RG",
        CModeArea.Dm => "RD",
        CModeArea.Auxiliary => "RJ",
        CModeArea.Em => "RE",
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown C-mode area."),
    };

    /// <summary>The write header (WR, WL, WH, WC, WD, WJ, WE); RG has none.</summary>
    public static string WriteHeader(CModeArea area) => area switch
    {
        CModeArea.Cio => "WR",
        CModeArea.Lr => "WL",
        CModeArea.Holding => "WH",
        CModeArea.TimerCounterPv => "WC",
        CModeArea.Dm => "WD",
        CModeArea.Auxiliary => "WJ",
        CModeArea.Em => "WE",
        CModeArea.TimerCounterStatus => throw new ArgumentException("Timer/counter completion flags cannot be written with C-mode (no WG on CS/CJ).", nameof(area)),
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown C-mode area."),
    };

    /// <summary>Finds the area and direction of a read or write header.</summary>
    public static bool TryFromHeader(ReadOnlySpan<byte> header, out CModeArea area, out bool write)
    {
        area = default;
        write = false;
        if (header.Length != 2 || (header[0] != 'R' && header[0] != 'W'))
        {
            return false;
        }

        write = header[0] == 'W';
        switch ((char)header[1])
        {
            case 'R': area = CModeArea.Cio; return true;
            case 'L': area = CModeArea.Lr; return true;
            case 'H': area = CModeArea.Holding; return true;
            case 'C': area = CModeArea.TimerCounterPv; return true;
            case 'G': area = CModeArea.TimerCounterStatus; return !write;
            case 'D': area = CModeArea.Dm; return true;
            case 'J': area = CModeArea.Auxiliary; return true;
            case 'E': area = CModeArea.Em; return true;
            default: return false;
        }
    }

    /// <summary>The number of addressable entries (words or points) of the area, counted from 0.</summary>
    public static int Size(CModeArea area) => area switch
    {
        CModeArea.Cio => 6144,
        CModeArea.Lr => 200,
        CModeArea.Holding => 512,
        CModeArea.TimerCounterPv or CModeArea.TimerCounterStatus => 2 * CounterOffset,
        CModeArea.Dm => 10000,
        CModeArea.Auxiliary => 960,
        CModeArea.Em => 10000,
        _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown C-mode area."),
    };

    /// <summary>Characters of the bank number that EM commands (RE, WE) carry before the begin word; 0 for other areas.</summary>
    public static int BankLength(CModeArea area) => area == CModeArea.Em ? 2 : 0;

    /// <summary>Writes the bank number of an EM command (two hex digits); writes nothing for another area.</summary>
    /// <returns>The number of characters written (<see cref="BankLength"/>).</returns>
    public static int WriteBank(CModeArea area, int bank, Span<byte> destination)
    {
        if (area != CModeArea.Em)
        {
            return 0;
        }

        HexAscii.WriteByte((byte)bank, destination);
        return BankLength(area);
    }

    /// <summary>Characters a read response spends on one entry: 4 hex digits a word, 1 character a completion flag.</summary>
    public static int CharactersPerEntry(CModeArea area) => area == CModeArea.TimerCounterStatus ? 1 : 4;

    /// <summary>A name for messages, as CX-Programmer users know the area.</summary>
    public static string DisplayName(CModeArea area) => area switch
    {
        CModeArea.Cio => "CIO",
        CModeArea.Lr => "LR",
        CModeArea.Holding => "HR",
        CModeArea.TimerCounterPv => "timer/counter PV",
        CModeArea.TimerCounterStatus => "timer/counter completion flag",
        CModeArea.Dm => "DM",
        CModeArea.Auxiliary => "AR",
        CModeArea.Em => "EM",
        _ => area.ToString(),
    };

    /// <summary>Checks a range of entries for a read or write and throws a message in the user's words when it does not fit.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The range does not fit the area, the count is 0, or the bank is not 0-C.</exception>
    public static void CheckRange(CModeArea area, int begin, int count, int bank, bool write)
    {
        string header = write ? WriteHeader(area) : ReadHeader(area);
        int size = Size(area);
        // Which words a model lets a host write is the model's (A0–A447 on CS/CJ, every AR word on the C series):
        // the client checks it against the PLC's profile, the simulator against the model it emulates.
        const int first = 0;
        if (area == CModeArea.Em && (uint)bank > MaxEmBank)
        {
            throw new ArgumentOutOfRangeException(nameof(bank), bank, $"EM bank {bank:X} is not reachable with C-mode {header}; banks 0-C exist.");
        }

        if (area != CModeArea.Em && bank != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(bank), bank, $"Only the EM area has banks; {header} takes none.");
        }

        if (begin < first || begin >= size)
        {
            throw new ArgumentOutOfRangeException(nameof(begin), begin, $"{DisplayName(area)} word {begin} is outside the range {first}-{size - 1} that C-mode {header} reaches.");
        }

        if (count < 1 || count > 9999)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"C-mode {header} takes a count of 1-9999; it was {count}.");
        }

        if (begin + count > size)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"{count} entries from {DisplayName(area)} {begin} run past the end of the range C-mode {header} reaches ({size - 1}).");
        }
    }
}
