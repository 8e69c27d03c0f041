using System.Diagnostics.Metrics;
using Microsoft.Extensions.Logging;
using OmronHostLink.Link;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>How a <see cref="HostLinkClient"/> talks to its PLCs. The defaults suit a CS/CJ at 9600 7E2.</summary>
public sealed class HostLinkClientOptions
{
    /// <summary>The unit number the client itself addresses (0-31); other units through <see cref="HostLinkUnit.Unit(int)"/>.</summary>
    public int UnitNumber { get; set; }

    /// <summary>
    /// The line's character timing used for deadlines when the transport does not know it (TCP, streams).
    /// Defaults to 9600 bps, 11 bits a character.
    /// </summary>
    public LineTiming LineTiming { get; set; } = LineTiming.Default;

    /// <summary>
    /// The time the PLC (and anything between it and us: a gateway, a network) may take to start answering a frame.
    /// Each frame's deadline is this plus the frame's wire time. Default 300 ms.
    /// </summary>
    public TimeSpan TurnaroundAllowance { get; set; } = TimeSpan.FromMilliseconds(300);

    /// <summary>How many times a read is repeated after a timeout or a damaged frame (ours or the PLC's: 13, A3). Default 2.</summary>
    public int ReadRetries { get; set; } = 2;

    /// <summary>
    /// How many times a write is repeated after a timeout or damaged frame. Default 0: a write whose answer was lost may
    /// have been executed, so repeating it is the caller's decision.
    /// </summary>
    public int WriteRetries { get; set; }

    /// <summary>
    /// Which command set (C-mode or FINS) reads, writes, bits, status and mode use. Default C-mode, which every Host
    /// Link PLC speaks; FINS (CS/CJ/CP) reaches what C-mode cannot: the work area (W), DM/EM beyond 9999, and bit writes.
    /// A C-mode client refuses those before anything is sent and says how to switch: this option, or a FINS view of one
    /// unit, <c>plc.Unit(0, HostLinkCommandSet.Fins)</c>. The FINS services (clock, CPU data, forcing …) use FINS on either.
    /// </summary>
    public HostLinkCommandSet CommandSet { get; set; } = HostLinkCommandSet.CMode;

    /// <summary>
    /// Lets a C-mode client write bits (C-mode has no bit write) by reading the word, changing the bit and writing the
    /// word back: for PLCs without FINS. Off by default, and a C-mode client refuses bit writes: anything that changes
    /// the word between the read and the write (the PLC program) is overwritten. With FINS bits are written directly.
    /// </summary>
    public bool AllowReadModifyWriteBits { get; set; }

    /// <summary>Word order for 32-bit values (Omron: low word first).</summary>
    public WordOrder WordOrder { get; set; } = WordOrder.LowWordFirst;

    /// <summary>
    /// Whether C-mode planned reads (<c>ReadTagsAsync</c>, <c>WatchAsync</c>) may use QQ, the compound read (QQMR
    /// registration once, then one QQIR a cycle), where it costs fewer characters than area reads: 100 scattered tags
    /// at 9600 bps read several times faster. <see cref="CompoundReadMode.Auto"/> (the default): QQ for a unit whose
    /// model profile lists it — the configured <see cref="Model"/>, or the model the unit names when asked MM once (by a
    /// <c>ReadTagsAsync</c> before it reads, by a watch after its first successful cycle), also when no model is
    /// configured — and area reads for the others (the CP2E, C200H and C200HX
    /// profiles, a PLC that refuses MM or names a code no profile has). <see cref="CompoundReadMode.On"/>: QQ unless
    /// the unit's model is known to lack it (no MM asked); <see cref="CompoundReadMode.Off"/>: area reads only. A unit
    /// that answers QQ with IC (or 14, 16, 18) though its model claims it is read by area from then on, the same cycle
    /// included, and the client logs it once. Profiles with QQ: CS/CJ (W342 p168), C200HS (p428), CQM1, CPM1/CPM1A,
    /// SRM1 (CPM-Q p388), CQM1H (p470), CPM2A/CPM2C (W353 p302); docs/models.md.
    /// </summary>
    public CompoundReadMode UseCompoundRead { get; set; }

    /// <summary>
    /// The line echoes what we send before the PLC answers (2-wire RS-485 adapters without echo suppression): expect and
    /// check our own frames before each answer.
    /// </summary>
    public bool LocalEcho { get; set; }

    /// <summary>
    /// Sends a TS (TEST) with a fresh random token behind every C-mode answer and takes the answer only when the token
    /// comes back as the next frame, for lines known to deliver answers out of turn (radio modems, protocol converters,
    /// serial-device servers that buffer). Off by default: every C-mode answer is already refused when it arrives before
    /// its command could have crossed the line, a frame that arrives while no command is outstanding makes the next
    /// command fence first, and while a unit's line may be delivering out of turn (an answer of the unit owed after a
    /// timeout, or a frame of it nobody asked for seen within an owed answer's lifetime) its answers get this check
    /// anyway (docs/reliability.md says what each catches). With this on, every C-mode answer is checked, and a read
    /// carried while the unit's line may be delivering out of turn is carried twice and taken only when both answers agree; the check costs one TS
    /// exchange per command (about 17 characters each way), and the unit's response time in metrics includes it. FINS
    /// answers carry their command's service ID and need no check.
    /// </summary>
    public bool VerifyAnswers { get; set; }

    /// <summary>The FINS response wait time, 0-15 in units of 10 ms, sent in every FA frame.</summary>
    public int FinsResponseWait { get; set; }

    /// <summary>
    /// The least time between the end of one exchange on the line and the next command, for PLCs and converters that
    /// drop a command sent right after an answer. Every command on the link waits for it, whichever unit it is for.
    /// Default zero (none); at most 10 s.
    /// </summary>
    public TimeSpan SendInterval { get; set; }

    /// <summary>
    /// Longer gaps than <see cref="SendInterval"/> before commands to particular units of a multidrop line (unit number
    /// to gap), for one slow unit among quick ones. Empty by default.
    /// </summary>
    public IDictionary<int, TimeSpan> UnitSendIntervals { get; set; } = new Dictionary<int, TimeSpan>();

    /// <summary>Where the client logs (frames at Trace, transactions at Debug, retries as warnings).</summary>
    public ILoggerFactory? LoggerFactory { get; set; }

    /// <summary>
    /// Where the client's meter (<see cref="HostLinkTelemetry.MeterName"/>) comes from: the container's factory in a
    /// host (the DI package passes it), so that the meter is scoped to the container and tests can collect from it.
    /// Null (the default) for the library's one shared static meter. A meter made by the factory belongs to it: the
    /// client never disposes it.
    /// </summary>
    public IMeterFactory? MeterFactory { get; set; }

    /// <summary>
    /// The link's name in metrics and traces (the <c>hostlink.link.name</c> attribute), which tells two clients apart.
    /// Null (the default) for the port name (<c>COM3</c>, <c>/dev/ttyUSB0</c>) or <c>host:port</c>; the DI package
    /// sets the client's registered name. Keep it to a few distinct values: every name is its own time series.
    /// </summary>
    public string? LinkName { get; set; }

    /// <summary>
    /// A file every frame the client sends and receives is written to, with its time and direction, for field
    /// diagnosis: a pcap (any name not ending in <c>.jsonl</c>, <c>.ndjson</c> or <c>.json</c>) that Wireshark and tshark
    /// decode with the Host Link dissector in the repository's tools/wireshark folder, or JSON lines (one object a
    /// frame) for those endings. The file is created (or replaced) when the client is, flushed within a second of each
    /// frame, and closed with the client. Null (the default): no trace, and the link pays one null check a frame.
    /// </summary>
    public string? TraceFile { get; set; }

    /// <summary>The clock frame deadlines run on. Default <see cref="TimeProvider.System"/>; tests pass a fake one.</summary>
    public TimeProvider TimeProvider { get; set; } = TimeProvider.System;

    /// <summary>
    /// The PLC model addresses, counts and commands are checked against before anything is sent (see
    /// <see cref="PlcModelProfile.All"/> and docs/models.md): a name such as <c>CPM1A</c>, <c>CP1E-E</c>, <c>C200HS</c>
    /// or <c>CJ2</c>; <c>"auto"</c> to ask each unit MM once, on first use, and use the model it names; null (the
    /// default) to check the CS/CJ sizes only.
    /// </summary>
    public string? Model { get; set; }

    /// <summary>
    /// The Host Link-compatible device mode the PLC's Serial Communications Unit (unit version 1.2 or later) is set to,
    /// when the client talks to one: each answer frame of an area read is then checked to carry the words (or RG
    /// flags) that mode sends, so that a unit set otherwise is reported instead of read (W336 4-6-2; docs/models.md).
    /// Null (the default) accepts any framing: answers are read correctly in every mode either way, and the MS message
    /// is read the same whether the unit leaves it out or sends spaces. Applies to every unit of the client.
    /// </summary>
    public HostLinkCompatibleMode? HostLinkCompatibleMode { get; set; }

    /// <summary>Checks the options and says what is wrong.</summary>
    /// <exception cref="ArgumentException">An option is out of range.</exception>
    public void Validate()
    {
        // The rules are the settings' own (SettingRules): one check, whichever way the values arrive.
        Check(nameof(UnitNumber), UnitNumber, SettingRules.UnitNumber(UnitNumber));
        if (LineTiming is null)
        {
            throw new ArgumentException("LineTiming is required.", nameof(LineTiming));
        }

        Check(nameof(TurnaroundAllowance), TurnaroundAllowance, SettingRules.TurnaroundAllowance(TurnaroundAllowance));
        Check(nameof(ReadRetries), ReadRetries, SettingRules.Retries(ReadRetries));
        Check(nameof(WriteRetries), WriteRetries, SettingRules.Retries(WriteRetries));
        Check(nameof(FinsResponseWait), FinsResponseWait, SettingRules.FinsResponseWait(FinsResponseWait));
        Check(nameof(CommandSet), CommandSet, SettingRules.Defined(CommandSet));
        Check(nameof(WordOrder), WordOrder, SettingRules.Defined(WordOrder));
        Check(nameof(SendInterval), SendInterval, SettingRules.SendInterval(SendInterval));
        Check(nameof(UseCompoundRead), UseCompoundRead, SettingRules.Defined(UseCompoundRead));

        if (UnitSendIntervals is null)
        {
            throw new ArgumentException("UnitSendIntervals is required (empty for none).", nameof(UnitSendIntervals));
        }

        Check(nameof(UnitSendIntervals), UnitSendIntervals, SettingRules.UnitSendIntervals(UnitSendIntervals));

        if (TimeProvider is null)
        {
            throw new ArgumentException("TimeProvider is required.", nameof(TimeProvider));
        }

        if (HostLinkCompatibleMode is { } compatibleMode)
        {
            Check(nameof(HostLinkCompatibleMode), compatibleMode, SettingRules.Defined(compatibleMode));
        }

        if (Model is not null && PlcModelProfile.CheckSetting(Model) is { } modelProblem)
        {
            throw new ArgumentException($"Model {modelProblem}.", nameof(Model));
        }

        if (TraceFile is not null && SettingRules.TraceFile(TraceFile) is { } traceProblem)
        {
            throw new ArgumentException($"TraceFile {traceProblem}.", nameof(TraceFile));
        }

        if (LinkName is not null && LinkName.Trim().Length == 0)
        {
            throw new ArgumentException("LinkName is empty; leave it unset (null) to name the link by its port or host:port.", nameof(LinkName));
        }
    }

    private static void Check(string name, object value, string? problem)
    {
        if (problem is not null)
        {
            throw new ArgumentOutOfRangeException(name, value, $"{name} {problem}.");
        }
    }

    internal HostLinkClientOptions Clone()
    {
        var clone = (HostLinkClientOptions)MemberwiseClone();
        if (UnitSendIntervals is not null)
        {
            clone.UnitSendIntervals = new Dictionary<int, TimeSpan>(UnitSendIntervals);
        }

        return clone;
    }

    /// <summary>The part of these options the link itself uses.</summary>
    internal HostLinkConnectionOptions ToConnectionOptions() => new()
    {
        LineTiming = LineTiming,
        TurnaroundAllowance = TurnaroundAllowance,
        LocalEcho = LocalEcho,
        VerifyAnswers = VerifyAnswers,
        LoggerFactory = LoggerFactory,
        MeterFactory = MeterFactory,
        LinkName = LinkName,
        SendInterval = SendInterval,
        UnitSendIntervals = UnitSendIntervals.Count == 0 ? null : new Dictionary<int, TimeSpan>(UnitSendIntervals),
        TimeProvider = TimeProvider,
        TraceFile = TraceFile,
        AnswerFraming = HostLinkCompatibleMode is { } mode ? CompatibleModeFraming.Of(mode) : null,
    };
}
