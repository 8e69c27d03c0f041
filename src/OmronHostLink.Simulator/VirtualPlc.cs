using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Simulator.Memory;

namespace OmronHostLink.Simulator;

/// <summary>
/// The memory and state of one simulated CS/CJ CPU Unit: CIO 6144 words, W 512, H 512, A 960, D 32768,
/// timer and counter present values and completion flags (4096 each), EM banks 0-C of 32768 words, forced bits,
/// operating mode, error information, FAL/FALS message and model code. Every member is thread-safe; one instance can
/// serve several sessions, at once or one after the other (<see cref="RunAsync"/>).
/// </summary>
/// <remarks>
/// The memory API here is the test and tool view of the PLC: it writes any word, whatever the mode, including the
/// read-only auxiliary words A0-A447. The rules a host meets (writes refused in RUN mode, A0-A447 read-only, C-mode
/// ranges) are applied by <see cref="Protocol.HostLinkResponder"/>.
/// </remarks>
public sealed class VirtualPlc : OmronHostLink.Protocol.Fins.IFinsPlc
{
    /// <summary>The number of EM banks (0-C).</summary>
    public const int EmBankCount = PlcAreaInfo.EmBankCount;

    /// <summary>Words per EM bank.</summary>
    public static int EmBankSize { get; } = PlcAddress.AreaSize(PlcArea.Em);

    private readonly object _gate = new();
    private readonly ushort[] _cio = new ushort[PlcAddress.AreaSize(PlcArea.Cio)];
    private readonly ushort[] _work = new ushort[PlcAddress.AreaSize(PlcArea.Work)];
    private readonly ushort[] _holding = new ushort[PlcAddress.AreaSize(PlcArea.Holding)];
    private readonly ushort[] _auxiliary = new ushort[PlcAddress.AreaSize(PlcArea.Auxiliary)];
    private readonly ushort[] _dm = new ushort[PlcAddress.AreaSize(PlcArea.Dm)];
    private readonly ushort[] _timers = new ushort[PlcAddress.AreaSize(PlcArea.Timer)];
    private readonly ushort[] _counters = new ushort[PlcAddress.AreaSize(PlcArea.Counter)];
    private readonly bool[] _timerFlags = new bool[PlcAddress.AreaSize(PlcArea.Timer)];
    private readonly bool[] _counterFlags = new bool[PlcAddress.AreaSize(PlcArea.Counter)];
    private readonly ushort[][] _em = new ushort[EmBankCount][];
    private readonly ForcedBits _forced = new();
    private PlcMode _mode;
    private byte _modelCode;
    private string? _falMessage;
    private ushort _error1;
    private ushort _error2;
    private TimeSpan _clockOffset;
    private bool _umProtected;
    private readonly Dictionary<(int Unit, string Key), object> _unitState = new();

    /// <summary>MS program area code 011: 30K steps.</summary>
    private const int ProgramAreaThirtyKSteps = 0b011;

    /// <summary>Creates a PLC with the given options (or the defaults: unit 0, PROGRAM mode, model code 30).</summary>
    /// <param name="options">Units, initial mode and memory, wire-time emulation, faults. The instance is kept; do not change it once sessions run.</param>
    /// <exception cref="ArgumentException">The options are not valid.</exception>
    /// <exception cref="FormatException">The initial memory file does not follow the format of <see cref="InitialMemory"/>.</exception>
    /// <exception cref="IOException">The initial memory file cannot be read.</exception>
    public VirtualPlc(VirtualPlcOptions? options = null)
    {
        Options = options ?? new VirtualPlcOptions();
        Options.Validate();
        for (int i = 0; i < EmBankCount; i++)
        {
            _em[i] = new ushort[EmBankSize];
        }

        _mode = Options.InitialMode;
        Model = Options.Model is { } name ? PlcModelProfile.Parse(name) : null;
        _modelCode = Model?.ModelCode ?? Options.ModelCode;
        Faults = new FaultInjector(Options.Faults);
        if (Options.InitialMemoryFile is { } file)
        {
            LoadJsonFile(file);
        }
    }

    /// <summary>The model the PLC emulates (<see cref="VirtualPlcOptions.Model"/>), or null for a CS/CJ CPU.</summary>
    public PlcModelProfile? Model { get; }

    /// <summary>The options the PLC was created with.</summary>
    public VirtualPlcOptions Options { get; }

    /// <summary>How many faults of each kind have been injected so far, over every session.</summary>
    public FaultCounters FaultCounters => Faults.Counters;

    /// <summary>The operating mode. Host Link SC changes it; MS reports it.</summary>
    public PlcMode Mode
    {
        get
        {
            lock (_gate)
            {
                return _mode;
            }
        }

        set
        {
            if (value is not (PlcMode.Program or PlcMode.Monitor or PlcMode.Run))
            {
                throw new ArgumentOutOfRangeException(nameof(value), value, "The mode must be PROGRAM, MONITOR or RUN.");
            }

            lock (_gate)
            {
                _mode = value;
            }
        }
    }

    /// <summary>The model code MM reports (0x30 = CS/CJ).</summary>
    public byte ModelCode
    {
        get
        {
            lock (_gate)
            {
                return _modelCode;
            }
        }

        set
        {
            lock (_gate)
            {
                _modelCode = value;
            }
        }
    }

    /// <summary>
    /// The FAL/FALS message MS reports after the status word (at most 16 printable ASCII characters; MS pads it with
    /// spaces), or null when no message is set.
    /// </summary>
    /// <exception cref="ArgumentException">The message is longer than 16 characters or holds a character that cannot travel in a frame.</exception>
    public string? FalMessage
    {
        get
        {
            lock (_gate)
            {
                return _falMessage;
            }
        }

        set
        {
            if (value is not null)
            {
                if (value.Length > 16)
                {
                    throw new ArgumentException($"A FAL/FALS message has at most 16 characters; '{value}' has {value.Length}.", nameof(value));
                }

                _ = OmronHostLink.Protocol.SafeText.ToAscii(value, nameof(value));
            }

            lock (_gate)
            {
                _falMessage = value;
            }
        }
    }

    /// <summary>
    /// Whether the user program memory is write-protected (the CPU's DIP switch): bit 7 of the MS status word is 0 then.
    /// Default false.
    /// </summary>
    public bool UserMemoryWriteProtected
    {
        get
        {
            lock (_gate)
            {
                return _umProtected;
            }
        }

        set
        {
            lock (_gate)
            {
                _umProtected = value;
            }
        }
    }

    /// <summary>
    /// The low byte of the MS status word (W342 4-3-23): bit 7 set when UM is not write-protected, bits 6-4 the
    /// program area size (011: 30K steps, a CS1/CJ1 CPU's), bits 3-0 zero.
    /// </summary>
    internal byte StatusLowByte => (byte)((UserMemoryWriteProtected ? 0x00 : 0x80) | (ProgramAreaThirtyKSteps << 4));

    /// <summary>The two words of error information MF reports.</summary>
    public PlcErrorInfo Errors
    {
        get
        {
            lock (_gate)
            {
                return new PlcErrorInfo(_error1, _error2);
            }
        }
    }

    /// <summary>The PLC's clock (FINS 0701/0702): local time plus an offset that setting it changes.</summary>
    public DateTime Clock
    {
        get
        {
            lock (_gate)
            {
                return DateTime.Now + _clockOffset;
            }
        }

        set
        {
            lock (_gate)
            {
                _clockOffset = value - DateTime.Now;
            }
        }
    }

    /// <summary>The lock every member takes; hold it to make several calls one consistent snapshot.</summary>
    internal object SyncRoot => _gate;

    /// <summary>The fault injector shared by the sessions of this PLC.</summary>
    internal FaultInjector Faults { get; }

    /// <summary>Sets the two words of error information MF reports.</summary>
    /// <param name="firstWord">The first word.</param>
    /// <param name="secondWord">The second word.</param>
    public void SetError(ushort firstWord, ushort secondWord)
    {
        lock (_gate)
        {
            _error1 = firstWord;
            _error2 = secondWord;
        }
    }

    /// <summary>Clears the error information (as MF with the clear flag does).</summary>
    public void ClearErrors() => SetError(0, 0);

    /// <summary>Reads words as a host sees them (forced bits applied).</summary>
    /// <param name="area">The area; <see cref="PlcArea.Timer"/> and <see cref="PlcArea.Counter"/> give present values.</param>
    /// <param name="start">The first word (or timer/counter number).</param>
    /// <param name="count">The number of words.</param>
    /// <param name="bank">The EM bank 0-12 for <see cref="PlcArea.Em"/>; 0 otherwise.</param>
    /// <returns>The words.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside the area.</exception>
    public ushort[] ReadWords(PlcArea area, int start, int count, int bank = 0)
    {
        PlcArea named = area;
        int first = start;
        (area, start) = Alias(area, start);
        ushort[] storage = Storage(area, bank);
        CheckRange(storage, area, start, count);
        var result = new ushort[count];
        lock (_gate)
        {
            for (int i = 0; i < count; i++)
            {
                // Memory the emulated model does not have reads 0000, as its manual says (C200HS RD, CPM1 RD, ...).
                result[i] = Model is not null && Model.ReadsZero(named, first + i, bank)
                    ? (ushort)0
                    : _forced.Apply(area, bank, start + i, storage[start + i]);
            }
        }

        return result;
    }

    /// <summary>Reads one word as a host sees it (forced bits applied).</summary>
    /// <param name="area">The area.</param>
    /// <param name="word">The word (or timer/counter number).</param>
    /// <param name="bank">The EM bank for <see cref="PlcArea.Em"/>.</param>
    /// <returns>The word.</returns>
    public ushort ReadWord(PlcArea area, int word, int bank = 0) => ReadWords(area, word, 1, bank)[0];

    /// <summary>Writes words; forced bits keep their forced state.</summary>
    /// <param name="area">The area; <see cref="PlcArea.Timer"/> and <see cref="PlcArea.Counter"/> take present values.</param>
    /// <param name="start">The first word (or timer/counter number).</param>
    /// <param name="words">The values.</param>
    /// <param name="bank">The EM bank 0-12 for <see cref="PlcArea.Em"/>; 0 otherwise.</param>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside the area.</exception>
    public void WriteWords(PlcArea area, int start, ReadOnlySpan<ushort> words, int bank = 0)
    {
        (area, start) = Alias(area, start);
        ushort[] storage = Storage(area, bank);
        CheckRange(storage, area, start, words.Length);
        lock (_gate)
        {
            for (int i = 0; i < words.Length; i++)
            {
                storage[start + i] = _forced.Apply(area, bank, start + i, words[i]);
            }
        }
    }

    /// <summary>Writes one word.</summary>
    /// <param name="area">The area.</param>
    /// <param name="word">The word (or timer/counter number).</param>
    /// <param name="value">The value.</param>
    /// <param name="bank">The EM bank for <see cref="PlcArea.Em"/>.</param>
    public void WriteWord(PlcArea area, int word, ushort value, int bank = 0) => WriteWords(area, word, [value], bank);

    /// <summary>Reads words from an address such as <c>D100</c>, <c>CIO0</c>, <c>H5</c>, <c>T3</c> or <c>E1_200</c>.</summary>
    /// <param name="address">The first word, written the CX-Programmer way.</param>
    /// <param name="count">The number of words.</param>
    /// <returns>The words.</returns>
    /// <exception cref="FormatException">The address cannot be parsed.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside the area.</exception>
    public ushort[] ReadWords(string address, int count)
    {
        PlcAddress a = PlcAddress.Parse(address);
        return ReadWords(a.Area, a.Word, count, a.Bank);
    }

    /// <summary>Writes words from an address such as <c>D100</c>.</summary>
    /// <param name="address">The first word, written the CX-Programmer way.</param>
    /// <param name="words">The values.</param>
    /// <exception cref="FormatException">The address cannot be parsed.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The range is outside the area.</exception>
    public void WriteWords(string address, ReadOnlySpan<ushort> words)
    {
        PlcAddress a = PlcAddress.Parse(address);
        WriteWords(a.Area, a.Word, words, a.Bank);
    }

    /// <summary>Reads one bit (forced state applied).</summary>
    /// <param name="area">A word area (not timers or counters: use <see cref="GetFlag"/>).</param>
    /// <param name="word">The word.</param>
    /// <param name="bit">The bit 0-15.</param>
    /// <param name="bank">The EM bank for <see cref="PlcArea.Em"/>.</param>
    /// <returns>Whether the bit is on.</returns>
    public bool GetBit(PlcArea area, int word, int bit, int bank = 0)
    {
        CheckBit(area, bit);
        return (ReadWord(area, word, bank) & (1 << bit)) != 0;
    }

    /// <summary>Sets or clears one bit (a forced bit keeps its forced state).</summary>
    /// <param name="area">A word area (not timers or counters: use <see cref="SetFlag"/>).</param>
    /// <param name="word">The word.</param>
    /// <param name="bit">The bit 0-15.</param>
    /// <param name="value">The new state.</param>
    /// <param name="bank">The EM bank for <see cref="PlcArea.Em"/>.</param>
    public void SetBit(PlcArea area, int word, int bit, bool value, int bank = 0)
    {
        CheckBit(area, bit);
        (area, word) = Alias(area, word);
        ushort[] storage = Storage(area, bank);
        CheckRange(storage, area, word, 1);
        lock (_gate)
        {
            int v = value ? storage[word] | (1 << bit) : storage[word] & ~(1 << bit);
            storage[word] = _forced.Apply(area, bank, word, (ushort)v);
        }
    }

    /// <summary>Reads a bit from an address such as <c>CIO100.05</c>, or a completion flag such as <c>T5</c>.</summary>
    /// <param name="address">The bit address, or a timer/counter number for its completion flag.</param>
    /// <returns>Whether the bit or flag is on.</returns>
    public bool GetBit(string address)
    {
        PlcAddress a = PlcAddress.Parse(address);
        if (a.Area is PlcArea.Timer or PlcArea.Counter)
        {
            return GetFlag(a.Area, a.Word);
        }

        if (!a.IsBit)
        {
            throw new ArgumentException($"'{address}' names a word, not a bit (write it like CIO100.05).", nameof(address));
        }

        return GetBit(a.Area, a.Word, a.Bit, a.Bank);
    }

    /// <summary>Sets a bit at an address such as <c>CIO100.05</c>, or a completion flag such as <c>C7</c>.</summary>
    /// <param name="address">The bit address, or a timer/counter number for its completion flag.</param>
    /// <param name="value">The new state.</param>
    public void SetBit(string address, bool value)
    {
        PlcAddress a = PlcAddress.Parse(address);
        if (a.Area is PlcArea.Timer or PlcArea.Counter)
        {
            SetFlag(a.Area, a.Word, value);
            return;
        }

        if (!a.IsBit)
        {
            throw new ArgumentException($"'{address}' names a word, not a bit (write it like CIO100.05).", nameof(address));
        }

        SetBit(a.Area, a.Word, a.Bit, value, a.Bank);
    }

    /// <summary>Reads a timer or counter completion flag (forced state applied).</summary>
    /// <param name="area"><see cref="PlcArea.Timer"/> or <see cref="PlcArea.Counter"/>.</param>
    /// <param name="number">The timer or counter number 0-4095.</param>
    /// <returns>Whether the flag is on.</returns>
    public bool GetFlag(PlcArea area, int number)
    {
        (area, number) = Alias(area, number);
        bool[] flags = Flags(area, number);
        lock (_gate)
        {
            return (_forced.Apply(area, 0, number, flags[number] ? (ushort)1 : (ushort)0) & 1) != 0;
        }
    }

    /// <summary>Sets a timer or counter completion flag (a forced flag keeps its forced state).</summary>
    /// <param name="area"><see cref="PlcArea.Timer"/> or <see cref="PlcArea.Counter"/>.</param>
    /// <param name="number">The timer or counter number 0-4095.</param>
    /// <param name="value">The new state.</param>
    public void SetFlag(PlcArea area, int number, bool value)
    {
        (area, number) = Alias(area, number);
        bool[] flags = Flags(area, number);
        lock (_gate)
        {
            flags[number] = (_forced.Apply(area, 0, number, value ? (ushort)1 : (ushort)0) & 1) != 0;
        }
    }

    /// <summary>Forces a bit on or off (KS/KR), or a timer/counter completion flag (bit 0).</summary>
    /// <param name="area">CIO, W, H or A, or <see cref="PlcArea.Timer"/>/<see cref="PlcArea.Counter"/> for a completion flag.</param>
    /// <param name="word">The word, or the timer/counter number.</param>
    /// <param name="bit">The bit 0-15; 0 for a completion flag.</param>
    /// <param name="on">True to force on, false to force off.</param>
    /// <exception cref="ArgumentException">The area cannot be forced.</exception>
    public void ForceBit(PlcArea area, int word, int bit, bool on)
    {
        CheckForceable(area, word, bit);
        lock (_gate)
        {
            _forced.Force(area, 0, word, bit, on);
            if (area is PlcArea.Timer or PlcArea.Counter)
            {
                Flags(area, word)[word] = on;
            }
            else
            {
                ushort[] storage = Storage(area, 0);
                storage[word] = _forced.Apply(area, 0, word, storage[word]);
            }
        }
    }

    /// <summary>Releases the forced state of one bit; the bit keeps the value it was forced to.</summary>
    /// <param name="area">CIO, W, H, A, or timer/counter.</param>
    /// <param name="word">The word, or the timer/counter number.</param>
    /// <param name="bit">The bit 0-15; 0 for a completion flag.</param>
    public void ReleaseForced(PlcArea area, int word, int bit)
    {
        CheckForceable(area, word, bit);
        lock (_gate)
        {
            _forced.Release(area, 0, word, bit);
        }
    }

    /// <summary>Releases every forced bit (KC).</summary>
    public void ReleaseAllForced()
    {
        lock (_gate)
        {
            _forced.Clear();
        }
    }

    /// <summary>Whether a bit is forced: true forced on, false forced off, null not forced.</summary>
    /// <param name="area">CIO, W, H, A, or timer/counter.</param>
    /// <param name="word">The word, or the timer/counter number.</param>
    /// <param name="bit">The bit 0-15; 0 for a completion flag.</param>
    /// <returns>The forced state.</returns>
    public bool? GetForced(PlcArea area, int word, int bit)
    {
        CheckForceable(area, word, bit);
        lock (_gate)
        {
            return _forced.State(area, 0, word, bit);
        }
    }

    /// <summary>Whether any bit is forced.</summary>
    public bool HasForcedBits
    {
        get
        {
            lock (_gate)
            {
                return _forced.Any;
            }
        }
    }

    /// <summary>Applies initial memory and state from a JSON document (format: <see cref="InitialMemory"/>).</summary>
    /// <param name="json">The JSON text.</param>
    /// <exception cref="FormatException">The document does not follow the format; the message names the key.</exception>
    public void LoadJson(string json) => InitialMemory.Apply(this, json);

    /// <summary>Applies initial memory and state from a JSON file (format: <see cref="InitialMemory"/>).</summary>
    /// <param name="path">The file.</param>
    /// <exception cref="FormatException">The document does not follow the format.</exception>
    /// <exception cref="IOException">The file cannot be read.</exception>
    public void LoadJsonFile(string path) => InitialMemory.Apply(this, File.ReadAllText(path));

    /// <summary>
    /// Serves one Host Link session over <paramref name="stream"/> (the PLC end of a serial line, a TCP connection or
    /// an in-memory link) until the stream ends or <paramref name="cancellationToken"/> is cancelled. Garbage on the line
    /// is skipped; the stream is not disposed.
    /// </summary>
    /// <param name="stream">The stream; the PLC reads commands from it and writes answers to it.</param>
    /// <param name="cancellationToken">Ends the session.</param>
    /// <returns>A task that completes when the session ends (never faulted by line errors or a closed stream).</returns>
    public Task RunAsync(Stream stream, CancellationToken cancellationToken = default)
        => new HostLinkSession(this).RunAsync(stream, cancellationToken);

    private static void CheckRange(ushort[] storage, PlcArea area, int start, int count)
    {
        if (start < 0 || count < 0 || start + count > storage.Length)
        {
            throw new ArgumentOutOfRangeException(nameof(start), start, $"{count} words from {start} do not fit the {area} area (0-{storage.Length - 1}).");
        }
    }

    private static void CheckBit(PlcArea area, int bit)
    {
        if (area is PlcArea.Timer or PlcArea.Counter)
        {
            throw new ArgumentException("Timers and counters have completion flags, not bits: use GetFlag/SetFlag.", nameof(area));
        }

        if ((uint)bit > 15)
        {
            throw new ArgumentOutOfRangeException(nameof(bit), bit, "A bit number is 0-15.");
        }
    }

    private void CheckForceable(PlcArea area, int word, int bit)
    {
        if (area is PlcArea.Timer or PlcArea.Counter)
        {
            _ = Flags(area, word);
            if (bit != 0)
            {
                throw new ArgumentOutOfRangeException(nameof(bit), bit, "A completion flag is forced as bit 0.");
            }

            return;
        }

        if (area is not (PlcArea.Cio or PlcArea.Work or PlcArea.Holding or PlcArea.Auxiliary))
        {
            throw new ArgumentException($"Bits of the {area} area cannot be forced; CIO, W, H, A and timer/counter flags can.", nameof(area));
        }

        CheckBit(area, bit);
        CheckRange(Storage(area, 0), area, word, 1);
    }

    // LR n is CIO 1000 + n; on a model whose timers and counters share one TC space, counter n is timer n.
    private (PlcArea Area, int Word) Alias(PlcArea area, int word)
    {
        if (area == PlcArea.Counter && Model is { SharesTimerCounterNumbers: true })
        {
            return (PlcArea.Timer, word);
        }

        return PlcAreaInfo.CioAlias(area, word);
    }

    private bool[] Flags(PlcArea area, int number)
    {
        bool[] flags = area switch
        {
            PlcArea.Timer => _timerFlags,
            PlcArea.Counter => _counterFlags,
            _ => throw new ArgumentException($"Only timers and counters have completion flags, not the {area} area.", nameof(area)),
        };
        if ((uint)number >= (uint)flags.Length)
        {
            throw new ArgumentOutOfRangeException(nameof(number), number, $"{area} numbers are 0-{flags.Length - 1}.");
        }

        return flags;
    }

    private ushort[] Storage(PlcArea area, int bank)
    {
        if (area != PlcArea.Em && bank != 0)
        {
            throw new ArgumentOutOfRangeException(nameof(bank), bank, "Only the EM area has banks.");
        }

        return area switch
        {
            PlcArea.Cio => _cio,
            PlcArea.Work => _work,
            PlcArea.Holding => _holding,
            PlcArea.Auxiliary => _auxiliary,
            PlcArea.Dm => _dm,
            PlcArea.Timer => _timers,
            PlcArea.Counter => _counters,
            PlcArea.Em when (uint)bank < EmBankCount => _em[bank],
            PlcArea.Em => throw new ArgumentOutOfRangeException(nameof(bank), bank, "EM banks are 0-12 (0-C)."),
            _ => throw new ArgumentOutOfRangeException(nameof(area), area, "Unknown area."),
        };
    }

    /// <summary>
    /// Restarts the PLC as a power cycle does: what commands registered per unit (the QQMR registration) is lost; the
    /// memory, mode and errors stay as they are (the simulator keeps its memory like a battery-backed one).
    /// </summary>
    public void Restart()
    {
        lock (_gate)
        {
            _unitState.Clear();
        }
    }

    byte OmronHostLink.Protocol.CMode.ICModePlc.StatusLowByte => StatusLowByte;

    /// <summary>What 0501 CPU UNIT DATA READ reports: a CJ1M's model name and the simulator's version text.</summary>
    OmronHostLink.Protocol.Fins.FinsCpuUnitData OmronHostLink.Protocol.Fins.IFinsPlc.UnitData { get; } = new("CJ1M-CPU13", "OmronHostLink.Sim");

    void OmronHostLink.Protocol.CMode.ICModePlc.SetBit(PlcArea area, int word, int bit, bool value) => SetBit(area, word, bit, value);

    object? OmronHostLink.Protocol.CMode.ICModePlc.GetUnitState(int unit, string key)
    {
        lock (_gate)
        {
            return _unitState.TryGetValue((unit, key), out object? value) ? value : null;
        }
    }

    void OmronHostLink.Protocol.CMode.ICModePlc.SetUnitState(int unit, string key, object? value)
    {
        lock (_gate)
        {
            if (value is null)
            {
                _unitState.Remove((unit, key));
            }
            else
            {
                _unitState[(unit, key)] = value;
            }
        }
    }
}
