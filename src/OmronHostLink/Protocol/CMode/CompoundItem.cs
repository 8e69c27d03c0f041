namespace OmronHostLink.Protocol.CMode;

/// <summary>The read areas QQMR names (W342 4-3-35; C200HS 11-3-33; CPM1 4-5-30), four characters each.</summary>
internal enum CompoundArea
{
    /// <summary><c>CIO </c>.</summary>
    Cio,

    /// <summary><c>LR  </c>: LR n is CIO 1000 + n on CS/CJ.</summary>
    Lr,

    /// <summary><c>HR  </c>.</summary>
    Holding,

    /// <summary><c>AR  </c>.</summary>
    Auxiliary,

    /// <summary><c>TIM </c>: a completion flag, or with <c>CH</c> the flag and the PV.</summary>
    Timer,

    /// <summary><c>CNT </c>: as <see cref="Timer"/>.</summary>
    Counter,

    /// <summary><c>DM  </c>.</summary>
    Dm,

    /// <summary><c>EM  </c> (current bank) or <c>EM</c> + bank.</summary>
    Em,
}

/// <summary>
/// One item of a QQMR registration: read area (4 characters), word (4 decimal digits) and data format (2 characters:
/// bit <c>00</c>–<c>15</c>, or <c>CH</c> for the word). For timers and counters <c>CH</c> reads the completion flag
/// and the PV (it counts as two of the 128 items); any other format reads the flag alone. The answer to QQIR carries
/// each item in registration order: a bit or flag as one character <c>0</c>/<c>1</c>, a word as four hex digits, a
/// timer/counter with <c>CH</c> as the flag followed by the PV.
/// </summary>
internal readonly struct CompoundItem : IEquatable<CompoundItem>
{
    /// <summary>Characters of one item in QQMR: area 4, word 4, format 2.</summary>
    public const int Length = 10;

    /// <summary>Characters of a word in the QQIR answer: four hex digits.</summary>
    public const int WordAnswerLength = 4;

    /// <summary>Characters of a bit (or a completion flag alone) in the QQIR answer: 0 or 1.</summary>
    public const int BitAnswerLength = 1;

    /// <summary>Characters of a timer/counter read with <c>CH</c> in the QQIR answer: the completion flag, then the PV.</summary>
    public const int TimerCounterAnswerLength = BitAnswerLength + WordAnswerLength;

    /// <summary>The most items one registration holds (a timer/counter PV counts as two).</summary>
    public const int MaxWeight = 128;

    /// <summary>Bank value for the EM bank currently selected in the PLC (<c>EM  </c>).</summary>
    public const int CurrentBank = -1;

    private CompoundItem(CompoundArea area, int word, int bit, int bank)
    {
        Area = area;
        Word = word;
        Bit = bit;
        Bank = bank;
    }

    /// <summary>The read area.</summary>
    public CompoundArea Area { get; }

    /// <summary>The word (timer/counter number).</summary>
    public int Word { get; }

    /// <summary>The bit 0–15, or -1 for the word (<c>CH</c>); for timers and counters 0 stands for the flag alone.</summary>
    public int Bit { get; }

    /// <summary>The EM bank 0–12, or <see cref="CurrentBank"/>; 0 for other areas.</summary>
    public int Bank { get; }

    /// <summary>Whether the item reads one bit (or a completion flag alone).</summary>
    public bool IsBit => Bit >= 0;

    /// <summary>Whether the item is a timer or counter read with <c>CH</c>: flag and PV.</summary>
    public bool IsTimerCounterWord => !IsBit && Area is CompoundArea.Timer or CompoundArea.Counter;

    /// <summary>Items of the 128 the item takes: 2 for a timer/counter PV, else 1.</summary>
    public int Weight => IsTimerCounterWord ? 2 : 1;

    /// <summary>Characters the item takes in the QQIR answer (without the comma before it).</summary>
    public int AnswerLength => IsBit ? BitAnswerLength : IsTimerCounterWord ? TimerCounterAnswerLength : WordAnswerLength;

    /// <summary>A word item.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The word or bank is beyond what QQ reaches.</exception>
    public static CompoundItem ForWord(CompoundArea area, int word, int bank = 0) => Create(area, word, -1, bank);

    /// <summary>A bit item (for timers and counters: the completion flag alone).</summary>
    /// <exception cref="ArgumentOutOfRangeException">The word, bit or bank is beyond what QQ reaches.</exception>
    public static CompoundItem ForBit(CompoundArea area, int word, int bit, int bank = 0) => Create(area, word, bit, bank);

    /// <summary>
    /// Whether QQ reads single bits of <paramref name="area"/>: CIO, LR, HR and AR (DM and EM are read as words whatever
    /// the format; a timer or counter's "bit" is its completion flag).
    /// </summary>
    public static bool ReadsBits(PlcArea area) => area is PlcArea.Cio or PlcArea.Link or PlcArea.Holding or PlcArea.Auxiliary;

    /// <summary>The item reading <paramref name="address"/>: its bit for a bit address of an area <see cref="ReadsBits"/>, else its word.</summary>
    /// <exception cref="ArgumentException">The address is in the work area, which C-mode cannot reach.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The address is beyond what QQ reaches.</exception>
    public static CompoundItem For(PlcAddress address)
    {
        CompoundArea area = address.Area switch
        {
            PlcArea.Cio => CompoundArea.Cio,
            PlcArea.Link => CompoundArea.Lr,
            PlcArea.Holding => CompoundArea.Holding,
            PlcArea.Auxiliary => CompoundArea.Auxiliary,
            PlcArea.Timer => CompoundArea.Timer,
            PlcArea.Counter => CompoundArea.Counter,
            PlcArea.Dm => CompoundArea.Dm,
            PlcArea.Em => CompoundArea.Em,
            _ => throw new ArgumentException($"{address} is in the {PlcAreaInfo.Name(address.Area)}, which C-mode cannot reach; {CommandSetAdvice.UseFins()}.", nameof(address)),
        };
        return address.IsBit && ReadsBits(address.Area) ? ForBit(area, address.Word, address.Bit, address.Bank) : ForWord(area, address.Word, address.Bank);
    }

    /// <summary>The PLC word (or timer/counter) the item names; EM's current bank is taken as <paramref name="currentBank"/>.</summary>
    public (PlcArea Area, int Word, int Bank) Locate(int currentBank = 0) => Area switch
    {
        CompoundArea.Cio => (PlcArea.Cio, Word, 0),
        CompoundArea.Lr => (PlcArea.Cio, CModeAreaInfo.LrCioStart + Word, 0),
        CompoundArea.Holding => (PlcArea.Holding, Word, 0),
        CompoundArea.Auxiliary => (PlcArea.Auxiliary, Word, 0),
        CompoundArea.Timer => (PlcArea.Timer, Word, 0),
        CompoundArea.Counter => (PlcArea.Counter, Word, 0),
        CompoundArea.Dm => (PlcArea.Dm, Word, 0),
        _ => (PlcArea.Em, Word, Bank == CurrentBank ? currentBank : Bank),
    };

    /// <summary>Writes the item's ten characters.</summary>
    public void Write(Span<byte> destination)
    {
        string name = Name(Area);
        for (int i = 0; i < 4; i++)
        {
            destination[i] = (byte)name[i];
        }

        if (Area == CompoundArea.Em && Bank != CurrentBank)
        {
            HexAscii.WriteByte((byte)Bank, destination.Slice(2, 2));
        }

        HexAscii.WriteDecimal(Word, destination.Slice(4, 4));
        if (IsBit)
        {
            HexAscii.WriteDecimal(Bit, destination.Slice(8, 2));
        }
        else
        {
            destination[8] = (byte)'C';
            destination[9] = (byte)'H';
        }
    }

    /// <summary>Reads one item as a PLC does; false (with the end code 15 reason) for an area, word or format it refuses.</summary>
    public static bool TryParse(ReadOnlySpan<byte> text, out CompoundItem item, out string? fault)
    {
        item = default;
        fault = null;
        if (text.Length != Length)
        {
            fault = $"A QQMR item has {Length} characters; this one has {text.Length}.";
            return false;
        }

        int bank = 0;
        CompoundArea? area = null;
        foreach (CompoundArea candidate in new[] { CompoundArea.Cio, CompoundArea.Lr, CompoundArea.Holding, CompoundArea.Auxiliary, CompoundArea.Timer, CompoundArea.Counter, CompoundArea.Dm, CompoundArea.Em })
        {
            string name = Name(candidate);
            if (text[0] == name[0] && text[1] == name[1] && text[2] == name[2] && text[3] == name[3])
            {
                area = candidate;
                bank = candidate == CompoundArea.Em ? CurrentBank : 0;
                break;
            }
        }

        if (area is null && text[0] == 'E' && text[1] == 'M' && HexAscii.TryParseByte(text.Slice(2, 2), out byte b))
        {
            area = CompoundArea.Em;
            bank = b;
        }

        if (area is null)
        {
            fault = $"'{FrameText.Printable(text.Slice(0, 4))}' is not a QQMR read area.";
            return false;
        }

        if (!HexAscii.TryParseDecimal(text.Slice(4, 4), out int word))
        {
            fault = "The word of a QQMR item is four decimal digits.";
            return false;
        }

        int bit;
        if (text[8] == 'C' && text[9] == 'H')
        {
            bit = -1;
        }
        else if (area is CompoundArea.Timer or CompoundArea.Counter)
        {
            bit = 0; // any other two characters: the completion flag alone
        }
        else if (area == CompoundArea.Dm || area == CompoundArea.Em)
        {
            bit = -1; // DM and EM are read as words whatever the format characters
        }
        else if (!HexAscii.TryParseDecimal(text.Slice(8, 2), out bit) || bit > 15)
        {
            fault = "The format of a QQMR bit item is 00-15, or CH for the word.";
            return false;
        }

        try
        {
            item = Create(area.Value, word, bit, bank);
            return true;
        }
        catch (ArgumentOutOfRangeException e)
        {
            fault = e.Message;
            return false;
        }
    }

    /// <inheritdoc/>
    public bool Equals(CompoundItem other) => Area == other.Area && Word == other.Word && Bit == other.Bit && Bank == other.Bank;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is CompoundItem other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => ((int)Area * 397) ^ (Word * 31) ^ (Bit * 7) ^ Bank;

    /// <inheritdoc/>
    public override string ToString()
    {
        Span<byte> text = stackalloc byte[Length];
        Write(text);
        return FrameText.Printable(text);
    }

    /// <summary>The four characters of an area.</summary>
    internal static string Name(CompoundArea area) => area switch
    {
        CompoundArea.Cio => "CIO ",
        CompoundArea.Lr => "LR  ",
        CompoundArea.Holding => "HR  ",
        CompoundArea.Auxiliary => "AR  ",
        CompoundArea.Timer => "TIM ",
        CompoundArea.Counter => "CNT ",
        CompoundArea.Dm => "DM  ",
        _ => "EM  ",
    };

    /// <summary>The number of words (timers, counters) of an area QQ reaches: the C-mode ranges of a CS/CJ.</summary>
    internal static int Size(CompoundArea area) => area switch
    {
        CompoundArea.Cio => CModeAreaInfo.Size(CModeArea.Cio),
        CompoundArea.Lr => CModeAreaInfo.Size(CModeArea.Lr),
        CompoundArea.Holding => CModeAreaInfo.Size(CModeArea.Holding),
        CompoundArea.Auxiliary => CModeAreaInfo.Size(CModeArea.Auxiliary),
        CompoundArea.Timer or CompoundArea.Counter => CModeAreaInfo.CounterOffset,
        CompoundArea.Dm => CModeAreaInfo.Size(CModeArea.Dm),
        _ => CModeAreaInfo.Size(CModeArea.Em),
    };

    private static CompoundItem Create(CompoundArea area, int word, int bit, int bank)
    {
        if ((uint)word >= (uint)Size(area))
        {
            throw new ArgumentOutOfRangeException(nameof(word), word, $"QQ reaches {Name(area).Trim()} 0-{Size(area) - 1}; {word} is beyond.");
        }

        if (bit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, "A bit is 0-15.");
        }

        if (area is CompoundArea.Timer or CompoundArea.Counter)
        {
            bit = bit >= 0 ? 0 : -1;
        }

        if (area == CompoundArea.Em)
        {
            if (bank != CurrentBank && (uint)bank > CModeAreaInfo.MaxEmBank)
            {
                throw new ArgumentOutOfRangeException(nameof(bank), bank, $"An EM bank for QQ is 0-{CModeAreaInfo.MaxEmBank}.");
            }
        }
        else
        {
            bank = 0;
        }

        return new CompoundItem(area, word, bit, bank);
    }
}
