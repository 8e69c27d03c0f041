namespace OmronHostLink.Simulator;

/// <summary>How a <see cref="VirtualPlc"/> starts and how it behaves on the line.</summary>
public sealed class VirtualPlcOptions
{
    /// <summary>The Host Link unit numbers (0-31) the PLC answers to; frames for any other unit are ignored. Default: unit 0.</summary>
    public IReadOnlyList<int> Units { get; set; } = [0];

    /// <summary>The operating mode at start. Default PROGRAM.</summary>
    public PlcMode InitialMode { get; set; } = PlcMode.Program;

    /// <summary>The model code MM reports. Default 0x30 (CS/CJ).</summary>
    public byte ModelCode { get; set; } = 0x30;

    /// <summary>
    /// The PLC model to emulate (a <see cref="PlcModelProfile"/> name such as <c>CPM1A</c>, <c>C200HS</c>, <c>CP1E-E</c>):
    /// its areas and ranges, its C-mode commands and FINS (IC for the others), its MM code (which then overrides
    /// <see cref="ModelCode"/>; IC where the manuals give none), end code 15 for words it does not have, and 0000 for the
    /// memory its manual says reads 0000. Null (the default): a CS/CJ CPU.
    /// </summary>
    public string? Model { get; set; }

    /// <summary>
    /// C-mode headers (such as <c>QQ</c>) the PLC answers with IC although its model lists them: a PLC that claims a
    /// command it lacks, or a converter that does not pass it. Empty by default.
    /// </summary>
    public IReadOnlyCollection<string> RefusedCommands { get; set; } = [];

    /// <summary>
    /// The Host Link-compatible device mode of a Serial Communications Unit to answer as (W336 4-6-2): the words each
    /// frame of an RR, RL, RH, RC, RD and RJ answer carries, the flags each RG frame carries, and whether MS sends the
    /// message characters as spaces when no FAL/FALS message is set. Null (the default): a CPU Unit's own port.
    /// <see cref="HostLinkCompatibleMode.ModeD"/> is not emulated: the manual pages found do not give all of it.
    /// </summary>
    public HostLinkCompatibleMode? HostLinkCompatibleMode { get; set; }

    /// <summary>
    /// A JSON file with initial memory and state, applied after the other options (so its <c>mode</c> and
    /// <c>model</c> win). Format: see <see cref="Memory.InitialMemory"/>. Null for none.
    /// </summary>
    public string? InitialMemoryFile { get; set; }

    /// <summary>
    /// The emulated line speed in bits per second; 0 (the default) sends answers as fast as the stream takes them.
    /// When set, each frame the PLC sends occupies the line for length × <see cref="BitsPerCharacter"/> / baud seconds.
    /// </summary>
    public int BaudRate { get; set; }

    /// <summary>Bits on the line per character: start + data + parity + stop. Default 11 (7E2: 1 + 7 + 1 + 2).</summary>
    public int BitsPerCharacter { get; set; } = 11;

    /// <summary>The PLC's turnaround: the time between the last byte of a command frame and the first byte of its answer. Default zero.</summary>
    public TimeSpan Turnaround { get; set; } = TimeSpan.Zero;

    /// <summary>Faults to inject into answers. Default none.</summary>
    public Faults.FaultOptions Faults { get; set; } = new();

    /// <summary>
    /// Where every frame the PLC's sessions receive and send is logged, with its times (and written to the log's capture
    /// file, if it has one). Shared, not copied, by <see cref="WithUnits"/>, so the PLCs of a line log to one; a line's
    /// sessions use its first PLC's. Null (the default): nothing is logged.
    /// </summary>
    public SimulatorFrameLog? FrameLog { get; set; }

    /// <summary>A copy of these options answering <paramref name="units"/> instead (the fault options are shared, not copied).</summary>
    /// <param name="units">The unit numbers.</param>
    /// <returns>The copy.</returns>
    public VirtualPlcOptions WithUnits(IReadOnlyList<int> units)
    {
        var copy = (VirtualPlcOptions)MemberwiseClone();
        copy.Units = units;
        return copy;
    }

    /// <summary>Checks the options.</summary>
    /// <exception cref="ArgumentException">A value is out of range.</exception>
    public void Validate()
    {
        if (Units is null || Units.Count == 0)
        {
            throw new ArgumentException("The PLC needs at least one unit number.", nameof(Units));
        }

        foreach (int unit in Units)
        {
            if (HostLinkRules.CheckUnitNumber(unit) is { } unitProblem)
            {
                throw new ArgumentException($"Units: {unitProblem}.", nameof(Units));
            }
        }

        if (Model is not null && !PlcModelProfile.TryParse(Model, out _))
        {
            throw new ArgumentException($"Model '{Model}' is not a known PLC model; known models: {PlcModelProfile.KnownNames()}.", nameof(Model));
        }

        if (HostLinkCompatibleMode is { } compatible && compatible is not (OmronHostLink.HostLinkCompatibleMode.ModeA or OmronHostLink.HostLinkCompatibleMode.ModeB or OmronHostLink.HostLinkCompatibleMode.ModeC))
        {
            throw new ArgumentException(
                compatible == OmronHostLink.HostLinkCompatibleMode.ModeD
                    ? "HostLinkCompatibleMode ModeD is not emulated: the manual pages found do not say what its later RG frames carry or how it answers MS. Use ModeA, ModeB or ModeC."
                    : $"HostLinkCompatibleMode {(int)compatible} is not ModeA, ModeB or ModeC.",
                nameof(HostLinkCompatibleMode));
        }

        if (RefusedCommands is null || RefusedCommands.Any(h => h is null || h.Length != 2))
        {
            throw new ArgumentException("RefusedCommands holds two-character C-mode headers such as QQ (empty for none).", nameof(RefusedCommands));
        }

        if (BaudRate < 0)
        {
            throw new ArgumentException("The baud rate cannot be negative.", nameof(BaudRate));
        }

        if (BitsPerCharacter is < 7 or > 12)
        {
            throw new ArgumentException("Bits per character (start + data + parity + stop) must be 7-12.", nameof(BitsPerCharacter));
        }

        if (Turnaround < TimeSpan.Zero)
        {
            throw new ArgumentException("The turnaround cannot be negative.", nameof(Turnaround));
        }

        if (Faults is null)
        {
            throw new ArgumentException("Faults cannot be null; use new FaultOptions() for none.", nameof(Faults));
        }

        Faults.Validate();
    }
}
