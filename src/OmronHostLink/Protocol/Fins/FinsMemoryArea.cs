namespace OmronHostLink.Protocol.Fins;

/// <summary>
/// FINS memory area codes of CS/CJ CPU Units (W342; gofins memory_area.go) and what each one addresses: the size of
/// one element in a response, and whether the address's bit field selects a bit.
/// </summary>
/// <remarks>
/// A word code reads or writes 2 bytes per word and requires bit 00; a bit code reads or writes 1 byte (00 or 01)
/// per bit and accepts bits 00–15. Timer and counter numbers share one address space: timer <c>n</c> is address
/// <c>n</c>, counter <c>n</c> is <c>0x8000 + n</c> [unverified for CS/CJ].
/// </remarks>
internal static class FinsMemoryArea
{
    /// <summary>CIO area, bit access.</summary>
    public const byte CioBit = 0x30;

    /// <summary>Work area, bit access.</summary>
    public const byte WorkBit = 0x31;

    /// <summary>Holding area, bit access.</summary>
    public const byte HoldingBit = 0x32;

    /// <summary>Auxiliary area, bit access.</summary>
    public const byte AuxiliaryBit = 0x33;

    /// <summary>CIO area, word access.</summary>
    public const byte CioWord = 0xB0;

    /// <summary>Work area, word access.</summary>
    public const byte WorkWord = 0xB1;

    /// <summary>Holding area, word access.</summary>
    public const byte HoldingWord = 0xB2;

    /// <summary>Auxiliary area, word access.</summary>
    public const byte AuxiliaryWord = 0xB3;

    /// <summary>CIO area bits with their forced status.</summary>
    public const byte CioBitForced = 0x70;

    /// <summary>Work area bits with their forced status.</summary>
    public const byte WorkBitForced = 0x71;

    /// <summary>Holding area bits with their forced status.</summary>
    public const byte HoldingBitForced = 0x72;

    /// <summary>CIO area words with their forced status (4 bytes per word [unverified]).</summary>
    public const byte CioWordForced = 0xF0;

    /// <summary>Work area words with their forced status (4 bytes per word [unverified]).</summary>
    public const byte WorkWordForced = 0xF1;

    /// <summary>Holding area words with their forced status (4 bytes per word [unverified]).</summary>
    public const byte HoldingWordForced = 0xF2;

    /// <summary>DM area, bit access.</summary>
    public const byte DmBit = 0x02;

    /// <summary>DM area, word access.</summary>
    public const byte DmWord = 0x82;

    /// <summary>Timer/counter completion flags.</summary>
    public const byte TimerCounterFlag = 0x09;

    /// <summary>Timer/counter completion flags with their forced status.</summary>
    public const byte TimerCounterFlagForced = 0x49;

    /// <summary>Timer/counter present values.</summary>
    public const byte TimerCounterPv = 0x89;

    /// <summary>EM bank 0, bit access; bank <c>n</c> (0–C) is this plus <c>n</c>.</summary>
    public const byte EmBank0Bit = 0x20;

    /// <summary>EM bank 0, word access; bank <c>n</c> (0–C) is this plus <c>n</c>.</summary>
    public const byte EmBank0Word = 0xA0;

    /// <summary>EM current bank, bit access.</summary>
    public const byte EmCurrentBankBit = 0x0A;

    /// <summary>EM current bank, word access.</summary>
    public const byte EmCurrentBankWord = 0x98;

    /// <summary>EM current bank number (2 bytes [unverified]).</summary>
    public const byte EmCurrentBankNumber = 0x9C;

    /// <summary>Task flags.</summary>
    public const byte TaskFlag = 0x06;

    /// <summary>Task status (1 byte per task [unverified]).</summary>
    public const byte TaskStatus = 0x46;

    /// <summary>Index register present values (4 bytes each).</summary>
    public const byte IndexRegister = 0xDC;

    /// <summary>Data register present values (2 bytes each).</summary>
    public const byte DataRegister = 0xBC;

    /// <summary>Clock pulses and condition flags (bit access).</summary>
    public const byte ConditionFlags = 0x07;

    /// <summary>The highest EM bank number <see cref="WordCode"/> and <see cref="BitCode"/> map (bank C; CS/CJ1).</summary>
    public const int MaxEmBank = PlcAreaInfo.EmBankCount - 1;

    /// <summary>The highest timer or counter number (CS/CJ: T/C 0000–4095).</summary>
    public const int MaxTimerCounterNumber = 4095;

    /// <summary>The FINS address of counter 0; counter <c>n</c> is this plus <c>n</c> [unverified for CS/CJ].</summary>
    public const int CounterAddressOffset = 0x8000;

    /// <summary>The word-access area code of <paramref name="kind"/>.</summary>
    /// <param name="kind">The area.</param>
    /// <param name="emBank">For <see cref="FinsAreaKind.Em"/>: the bank, 0–C. Must be 0 for every other area.</param>
    /// <exception cref="ArgumentException">The area has no word access (<see cref="FinsAreaKind.TimerCounterFlag"/>).</exception>
    /// <exception cref="ArgumentOutOfRangeException">The bank is out of range, or given for an area that has none.</exception>
    public static byte WordCode(FinsAreaKind kind, int emBank = 0)
    {
        CheckBank(kind, emBank);
        return kind switch
        {
            FinsAreaKind.Cio => CioWord,
            FinsAreaKind.Work => WorkWord,
            FinsAreaKind.Holding => HoldingWord,
            FinsAreaKind.Auxiliary => AuxiliaryWord,
            FinsAreaKind.Dm => DmWord,
            FinsAreaKind.TimerCounterPv => TimerCounterPv,
            FinsAreaKind.Em => (byte)(EmBank0Word + emBank),
            FinsAreaKind.EmCurrentBank => EmCurrentBankWord,
            FinsAreaKind.TimerCounterFlag => throw new ArgumentException("Timer/counter completion flags have no word access; use BitCode.", nameof(kind)),
            _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown memory area."),
        };
    }

    /// <summary>The bit-access area code of <paramref name="kind"/>.</summary>
    /// <param name="kind">The area.</param>
    /// <param name="emBank">For <see cref="FinsAreaKind.Em"/>: the bank, 0–C. Must be 0 for every other area.</param>
    /// <exception cref="ArgumentException">The area has no bit access (<see cref="FinsAreaKind.TimerCounterPv"/>).</exception>
    /// <exception cref="ArgumentOutOfRangeException">The bank is out of range, or given for an area that has none.</exception>
    public static byte BitCode(FinsAreaKind kind, int emBank = 0)
    {
        CheckBank(kind, emBank);
        return kind switch
        {
            FinsAreaKind.Cio => CioBit,
            FinsAreaKind.Work => WorkBit,
            FinsAreaKind.Holding => HoldingBit,
            FinsAreaKind.Auxiliary => AuxiliaryBit,
            FinsAreaKind.Dm => DmBit,
            FinsAreaKind.TimerCounterFlag => TimerCounterFlag,
            FinsAreaKind.Em => (byte)(EmBank0Bit + emBank),
            FinsAreaKind.EmCurrentBank => EmCurrentBankBit,
            FinsAreaKind.TimerCounterPv => throw new ArgumentException("Timer/counter present values have no bit access; use WordCode.", nameof(kind)),
            _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "Unknown memory area."),
        };
    }

    /// <summary>The FINS address (word field) of timer <paramref name="number"/> (0–4095): the number itself.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The number is outside 0–4095.</exception>
    public static ushort TimerAddress(int number)
    {
        Guard.InRange(number, 0, MaxTimerCounterNumber);
        return (ushort)number;
    }

    /// <summary>The FINS address (word field) of counter <paramref name="number"/> (0–4095): 0x8000 + number [unverified for CS/CJ].</summary>
    /// <exception cref="ArgumentOutOfRangeException">The number is outside 0–4095.</exception>
    public static ushort CounterAddress(int number)
    {
        Guard.InRange(number, 0, MaxTimerCounterNumber);
        return (ushort)(CounterAddressOffset + number);
    }

    /// <summary>Whether <paramref name="code"/> is a CS/CJ area code this library knows.</summary>
    public static bool IsDefined(byte code) => ElementSize(code) != 0;

    /// <summary>Whether <paramref name="code"/> addresses bits (the address's bit field selects a bit 00–15).</summary>
    public static bool IsBitArea(byte code) => code switch
    {
        CioBit or WorkBit or HoldingBit or AuxiliaryBit or DmBit or TimerCounterFlag or TimerCounterFlagForced
            or EmCurrentBankBit or CioBitForced or WorkBitForced or HoldingBitForced or TaskFlag or ConditionFlags => true,
        >= EmBank0Bit and <= EmBank0Bit + MaxEmBank => true,
        >= 0xE0 and <= 0xE8 => true,
        _ => false,
    };

    /// <summary>Bytes of a bit (or completion flag) in read data and write data.</summary>
    public const int BitSize = 1;

    /// <summary>Bytes of a word in read data and write data.</summary>
    public const int WordSize = 2;

    /// <summary>
    /// Bytes per element in read data and write data: 1 for bits (and task status), 2 for words, 4 for words with
    /// forced status and index registers; 0 for a code this library does not know.
    /// </summary>
    public static int ElementSize(byte code)
    {
        if (IsBitArea(code) || code == TaskStatus)
        {
            return BitSize;
        }

        return code switch
        {
            CioWord or WorkWord or HoldingWord or AuxiliaryWord or DmWord or TimerCounterPv or EmCurrentBankWord
                or EmCurrentBankNumber or DataRegister => WordSize,
            >= EmBank0Word and <= EmBank0Word + MaxEmBank => WordSize,
            >= 0x60 and <= 0x68 => WordSize,
            CioWordForced or WorkWordForced or HoldingWordForced or IndexRegister => 4,
            _ => 0,
        };
    }

    /// <summary>A short name of the area a code addresses, for messages (for example <c>DM word</c>).</summary>
    public static string Describe(byte code) => code switch
    {
        CioBit => "CIO bit",
        WorkBit => "WR bit",
        HoldingBit => "HR bit",
        AuxiliaryBit => "AR bit",
        CioWord => "CIO word",
        WorkWord => "WR word",
        HoldingWord => "HR word",
        AuxiliaryWord => "AR word",
        CioBitForced => "CIO bit with forced status",
        WorkBitForced => "WR bit with forced status",
        HoldingBitForced => "HR bit with forced status",
        CioWordForced => "CIO word with forced status",
        WorkWordForced => "WR word with forced status",
        HoldingWordForced => "HR word with forced status",
        DmBit => "DM bit",
        DmWord => "DM word",
        TimerCounterFlag => "timer/counter completion flag",
        TimerCounterFlagForced => "timer/counter completion flag with forced status",
        TimerCounterPv => "timer/counter PV",
        EmCurrentBankBit => "EM current bank bit",
        EmCurrentBankWord => "EM current bank word",
        EmCurrentBankNumber => "EM current bank number",
        TaskFlag => "task flag",
        TaskStatus => "task status",
        IndexRegister => "index register",
        DataRegister => "data register",
        ConditionFlags => "clock pulses/condition flags",
        >= EmBank0Bit and <= EmBank0Bit + MaxEmBank => $"EM bank {code - EmBank0Bit:X} bit",
        >= EmBank0Word and <= EmBank0Word + MaxEmBank => $"EM bank {code - EmBank0Word:X} word",
        >= 0xE0 and <= 0xE8 => $"EM (CJ2 additional bank) bit, code {code:X2}",
        >= 0x60 and <= 0x68 => $"EM (CJ2 additional bank) word, code {code:X2}",
        _ => $"unknown area {code:X2}",
    };

    private static void CheckBank(FinsAreaKind kind, int emBank)
    {
        if (kind == FinsAreaKind.Em)
        {
            if ((uint)emBank > MaxEmBank)
            {
                throw new ArgumentOutOfRangeException(nameof(emBank), emBank, $"The EM bank must be 0-C (0-{MaxEmBank}); it was {emBank}.");
            }
        }
        else if (emBank != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(emBank), emBank, $"Only the EM area has banks; {kind} was given bank {emBank}.");
        }
    }
}
