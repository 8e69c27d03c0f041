using OmronHostLink.Protocol.CMode;

namespace OmronHostLink;

/// <summary>
/// The model profiles, from the manuals (docs/models.md has the same table with links). A range that no manual page
/// found confirms is marked unverified; where nothing better than the CS/CJ bounds is known, those are used and said to be.
/// </summary>
internal static class PlcModelTable
{
    // The manuals, as rows cite them.
    private const string W342 = "W342 CS/CJ Communications Commands Reference";
    private const string C200HS = "C200HS Operation Manual";
    private const string C200HX = "C200HX/HG/HE Operation Manual";
    private const string CpmQ = "CQM1/CPM1/CPM1A/SRM1 Programming Manual";
    private const string W353 = "W353 CPM1/CPM1A/CPM2A/CPM2C/SRM1(-V2) Programming Manual";
    private const string Cqm1h = "CQM1H Programming Manual";
    private const string W614 = "W614 CP2E CPU Unit Software User's Manual";
    private const string NotFound = "no manual page found";
    private const string CsCjBounds = "no manual page found; the CS/CJ bounds, no tighter check";

    // C-mode headers. The older families' list is the C200HX/HS Host Link command section (C200HX p463–490); QQ, RE/WE and
    // WG are added where a manual lists them.
    private static readonly CModeCommandRow[] OlderCMode =
    [
        Read(CModeArea.Cio), Read(CModeArea.Lr), Read(CModeArea.Holding), Read(CModeArea.TimerCounterPv), Read(CModeArea.TimerCounterStatus), Read(CModeArea.Dm), Read(CModeArea.Auxiliary),
        Write(CModeArea.Cio), Write(CModeArea.Lr), Write(CModeArea.Holding), Write(CModeArea.TimerCounterPv), Write(CModeArea.Dm), Write(CModeArea.Auxiliary),
        CModeCommands.StatusRead, StatusChangeCommand.CommandRow, ErrorReadCommand.CommandRow, ForceBitCommand.SetRow, ForceBitCommand.ResetRow,
        MultipleForceCommand.CommandRow, CModeCommands.ForcedCancel, CModeCommands.ModelRead, CModeCommands.Test, CModeCommands.Abort,
    ];

    private static readonly CModeCommandRow[] EmCMode = [Read(CModeArea.Em), Write(CModeArea.Em)];
    private static readonly CModeCommandRow[] Qq = [CompoundCommands.RegisterRow, CompoundCommands.ReadRow];
    private static readonly CModeCommandRow[] CsCjCMode = [.. OlderCMode, .. EmCMode, .. Qq];
    private static readonly CModeCommandRow[] Cp1CMode = [.. OlderCMode, .. Qq];

    // The CQM1H's end code table (CQM1H p441, 6-2-2) lists WG and QQ beside the older list (RE/WE: the CPU61's EM).
    private static readonly CModeCommandRow[] Cqm1hCMode = [.. OlderCMode, CModeCommands.TcStatusWrite, .. Qq];

    // The CP2E's list (W614 p14-40): no LR, EM, forcing or QQ commands.
    private static readonly CModeCommandRow[] Cp2eCMode =
    [
        Read(CModeArea.Cio), Read(CModeArea.Holding), Read(CModeArea.TimerCounterPv), Read(CModeArea.TimerCounterStatus), Read(CModeArea.Dm), Read(CModeArea.Auxiliary),
        Write(CModeArea.Cio), Write(CModeArea.Holding), Write(CModeArea.TimerCounterPv), Write(CModeArea.Dm), Write(CModeArea.Auxiliary),
        CModeCommands.StatusRead, StatusChangeCommand.CommandRow, ErrorReadCommand.CommandRow, CModeCommands.Test,
    ];

    public static IReadOnlyList<PlcModelProfile> Profiles { get; } = Build();

    private static readonly Dictionary<byte, PlcModelProfile> ByModelCode = BuildByModelCode();

    public static PlcModelProfile? ForModelCode(byte code) => ByModelCode.TryGetValue(code, out var profile) ? profile : null;

    private static PlcModelProfile[] Build() =>
    [
        new(
            "C200H", "C200H", [], 0x12,
            [
                Rw(PlcArea.Cio, 0, 255, "C200H manual not found; IR 000–235 and SR 236–255 as the C-series docs describe", false),
                Rw(PlcArea.Link, 0, 63, NotFound, false),
                Rw(PlcArea.Holding, 0, 99, NotFound, false),
                Rw(PlcArea.Auxiliary, 0, 27, NotFound, false),
                Rw(PlcArea.Timer, 0, 511, NotFound, false),
                Rw(PlcArea.Counter, 0, 511, NotFound, false),
                Rw(PlcArea.Dm, 0, 1999, NotFound, false),
            ],
            [],
            OlderCMode, supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: W342 p141 (4-3-30); ranges: C200H manual not found"),
        new(
            "C200HS", "C200HS", [], 0x12,
            [
                Rw(PlcArea.Cio, 0, 252, C200HS + " p410 (11-3-8 WR: 0000–0511)"),
                Ro(PlcArea.Cio, 253, 255, C200HS + " p410 (WR to 253–255 writes nothing and reports no error)"),
                Rw(PlcArea.Cio, 256, 511, C200HS + " p410 (11-3-8 WR: 0000–0511)"),
                Rw(PlcArea.Link, 0, 63, C200HS + " p411 (11-3-9 WL: 0000–0063)"),
                Rw(PlcArea.Holding, 0, 99, C200HS + " p408 (11-3-3 RH: 0000–0099)"),
                Rw(PlcArea.Auxiliary, 0, 27, C200HS + " p410 (11-3-7 RJ: 0000–0027)"),
                Rw(PlcArea.Timer, 0, 511, C200HS + " p408 (11-3-4 RC: 0000–0511)"),
                Rw(PlcArea.Counter, 0, 511, C200HS + " p408 (11-3-4 RC: 0000–0511)"),
                Rw(PlcArea.Dm, 0, 6655, C200HS + " p409 (11-3-6 RD: DM 6656–6999 do not exist)"),
            ],
            [
                Rw(PlcArea.Dm, 6656, 6999, C200HS + " p409 (RD note 2: reads 0000, no error)"),
                Rw(PlcArea.Dm, 7000, 9999, "RD takes 0000–9999 (" + C200HS + " p409); what these answer is not stated", false),
            ],
            [.. OlderCMode, .. Qq], supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: W342 p141, " + C200HX + " p490; ranges: " + C200HS + " section 11-3 (p408–411); QQ: " + C200HS + " p428 (11-3-33)"),
        new(
            "C200HX", "C200HX/HG/HE", ["C200HG", "C200HE", "C200HX/HG/HE", "C200HX-HG-HE"], 0x12,
            [
                Rw(PlcArea.Cio, 0, 252, C200HX + " p465 (10-3-9 WR: 0000–0511)"),
                Ro(PlcArea.Cio, 253, 255, "as the C200HS (" + C200HS + " p410)", false),
                Rw(PlcArea.Cio, 256, 511, C200HX + " p465 (10-3-9 WR: 0000–0511)"),
                Rw(PlcArea.Link, 0, 63, "as the C200HS (" + C200HS + " p411)", false),
                Rw(PlcArea.Holding, 0, 99, "as the C200HS (" + C200HS + " p408)", false),
                Rw(PlcArea.Auxiliary, 0, 27, "as the C200HS (" + C200HS + " p410)", false),
                Rw(PlcArea.Timer, 0, 511, "as the C200HS (" + C200HS + " p408)", false),
                Rw(PlcArea.Counter, 0, 511, "as the C200HS (" + C200HS + " p408)", false),
                Rw(PlcArea.Dm, 0, 6655, C200HX + " p463 (10-3-6 RD)"),
            ],
            [
                Rw(PlcArea.Dm, 6656, 6999, C200HX + " p463 (RD: reads 0000, no error)"),
                Rw(PlcArea.Dm, 7000, 9999, C200HX + " p463 (extension DM: reads 0000 unless allocated in UM)"),
                Em(0, 6143, 3, C200HX + " p465 (RE: a bank the CPU lacks reads 0000); which CPU has which banks not found", false),
            ],
            [.. OlderCMode, .. EmCMode, CModeCommands.TcStatusWrite], supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: W342 p141, " + C200HX + " p490; ranges: " + C200HX + " section 10-3"),
        new(
            "CQM1", "CQM1", [], 0x11,
            [
                Rw(PlcArea.Cio, 0, 252, CpmQ + " p369 (6-3-8 WR: 0000–0252)"),
                Ro(PlcArea.Cio, 253, 255, CpmQ + " p388 (QQ reads IR/SR 0000–0255; WR stops at 0252, p369)"),
                Rw(PlcArea.Link, 0, 63, CpmQ + " p388 (QQ: LR 0000–0063)"),
                Rw(PlcArea.Holding, 0, 99, CpmQ + " p388 (QQ: HR 0000–0099)"),
                Rw(PlcArea.Auxiliary, 0, 27, CpmQ + " p369 (6-3-7 RJ: 0000–0027)"),
                Rw(PlcArea.Timer, 0, 511, CpmQ + " p388 (QQ: TIM/CNT 0000–0511)"),
                Rw(PlcArea.Counter, 0, 511, CpmQ + " p388 (QQ: TIM/CNT 0000–0511)"),
                Rw(PlcArea.Dm, 0, 6655, CpmQ + " p388 (QQ: DM 0000–6655)"),
            ],
            [],
            Cp1CMode, supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: W342 p141, " + C200HX + " p490; ranges: " + CpmQ + " section 6-3"),
        new(
            "CQM1H", "CQM1H", [], 0x11,
            Cqm1hAreas(withEm: false),
            [],
            Cqm1hCMode, supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "ranges: " + Cqm1h + " p470 (6-5 QQ); commands: " + Cqm1h + " p441 (6-2-2); MM code 11 as the CQM1 (the CQM1H MM page was not found)"),
        new(
            "CQM1H-CPU61", "CQM1H-CPU61", [], 0x11,
            Cqm1hAreas(withEm: true),
            [],
            [.. Cqm1hCMode, .. EmCMode], supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "ranges: " + Cqm1h + " p470 (6-5 QQ; only the CPU61 has EM); commands: " + Cqm1h + " p441 (6-2-2); MM code 11 as the CQM1 (not found for the CQM1H)"),
        new(
            "CPM1A", "CPM1/CPM1A", ["CPM1"], 0x11,
            [
                Rw(PlcArea.Cio, 0, 19, CpmQ + " p388 (QQ: IR/SR 0000–0019, 0200–0255); " + W353 + " p285 (WR)"),
                Rw(PlcArea.Cio, 200, 252, W353 + " p285 (4-5-8 WR: 0200–0252)"),
                Ro(PlcArea.Cio, 253, 255, W353 + " p285 (SR 253 is beyond the writable range)"),
                Rw(PlcArea.Link, 0, 15, CpmQ + " p388 (QQ: LR 0000–0015); " + W353 + " p285 (WL)"),
                Rw(PlcArea.Holding, 0, 19, CpmQ + " p388 (QQ: HR 0000–0019)"),
                Rw(PlcArea.Auxiliary, 0, 15, CpmQ + " p369 (6-3-7 RJ: 0000–0015)"),
                Rw(PlcArea.Timer, 0, 127, CpmQ + " p388 (QQ: TIM/CNT 0000–0127)"),
                Rw(PlcArea.Counter, 0, 127, CpmQ + " p388 (QQ: TIM/CNT 0000–0127)"),
                Rw(PlcArea.Dm, 0, 1023, CpmQ + " p388 (QQ: DM 0000–1023, 6144–6655)"),
                Rw(PlcArea.Dm, 6144, 6655, CpmQ + " p388 (QQ: DM 0000–1023, 6144–6655)"),
            ],
            [
                Rw(PlcArea.Dm, 1024, 6143, CpmQ + " p369 (RD note 1: reads 0000)"),
            ],
            Cp1CMode, supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: " + W353 + " p300 (4-5-26); ranges: " + CpmQ + " section 6-3, " + W353 + " section 4-5"),
        new(
            "SRM1", "SRM1", ["SRM1-V2"], 0x11,
            [
                Rw(PlcArea.Cio, 0, 19, CpmQ + " p388 (QQ: IR/SR 0000–0019, 0200–0255)"),
                Rw(PlcArea.Cio, 200, 252, W353 + " p285 (4-5-8 WR: 0200–0252)"),
                Ro(PlcArea.Cio, 253, 255, W353 + " p285 (SR 253 is beyond the writable range)"),
                Rw(PlcArea.Link, 0, 15, CpmQ + " p388 (QQ: LR 0000–0015)"),
                Rw(PlcArea.Holding, 0, 19, CpmQ + " p388 (QQ: HR 0000–0019)"),
                Rw(PlcArea.Auxiliary, 0, 15, CpmQ + " p369 (6-3-7 RJ: 0000–0015)"),
                Rw(PlcArea.Timer, 0, 127, CpmQ + " p388 (QQ: TIM/CNT 0000–0127)"),
                Rw(PlcArea.Counter, 0, 127, CpmQ + " p388 (QQ: TIM/CNT 0000–0127)"),
                Rw(PlcArea.Dm, 0, 2047, CpmQ + " p369 (RD note 1: SRM1 words 2048–6143 read 0000)"),
                Rw(PlcArea.Dm, 6144, 6655, CpmQ + " p388 (QQ: DM up to 6655)"),
            ],
            [
                Rw(PlcArea.Dm, 2048, 6143, CpmQ + " p369 (RD note 1: reads 0000)"),
            ],
            Cp1CMode, supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: " + W353 + " p300; ranges: " + CpmQ + " section 6-3"),
        new(
            "CPM2A", "CPM2A/CPM2C", ["CPM2C", "CPM2"], 0x11,
            [
                Rw(PlcArea.Cio, 0, 49, W353 + " p285 (4-5-8 WR: 0000–0049, 0200–0252)"),
                Rw(PlcArea.Cio, 200, 252, W353 + " p285 (4-5-8 WR: 0000–0049, 0200–0252)"),
                Ro(PlcArea.Cio, 253, 255, W353 + " p285 (SR 253 is beyond the writable range)"),
                Rw(PlcArea.Link, 0, 15, W353 + " p285 (4-5-9 WL: 0000–0015)"),
                Rw(PlcArea.Holding, 0, 19, NotFound, false),
                Rw(PlcArea.Auxiliary, 0, 23, NotFound, false),
                Rw(PlcArea.Timer, 0, 255, NotFound, false),
                Rw(PlcArea.Counter, 0, 255, NotFound, false),
                Rw(PlcArea.Dm, 0, 2047, NotFound, false),
                Rw(PlcArea.Dm, 6144, 6655, NotFound, false),
            ],
            [
                Rw(PlcArea.Dm, 2048, 6143, "as the SRM1 (" + CpmQ + " p369)", false),
            ],
            [.. OlderCMode, .. Qq], supportsFins: false, sharesTimerCounterNumbers: true, TimerCounterCoding.Bcd,
            "MM code: " + W353 + " p300; ranges: " + W353 + " section 4-5 (IR/SR, LR); the rest not found; QQ: " + W353 + " p302 (4-5-30)"),
        Cp1e("CP1E-E", "CP1E E-type", ["CP1E E", "CP1EE", "CP1E E-type"], 2047),
        Cp1e("CP1E-N", "CP1E N/NA-type", ["CP1E N", "CP1EN", "CP1E-NA", "CP1E N-type", "CP1E NA-type"], 8191),
        new(
            "CP2E", "CP2E", [], null,
            [.. CsCjAreas(CsCjBounds, verified: false, withEm: false, withLr: false)],
            [],
            Cp2eCMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
            "C-mode list and FINS: " + W614 + " p14-40 (14-6-3); ranges not found"),
        new(
            "CP1L-L", "CP1L L-type", ["CP1L L", "CP1L L-type"], null,
            Cp1lLAreas(),
            [],
            Cp1CMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
            "CP1L manual not found: DM and commands as the CP1L's published specifications state them, unverified"),
        new(
            "CP1L-M", "CP1L M-type", ["CP1L", "CP1L M", "CP1L M-type"], null,
            [.. CsCjAreas(CsCjBounds, verified: false, withEm: false, withLr: true)],
            [],
            Cp1CMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
            "CP1L manual not found: the CS/CJ bounds without EM, unverified"),
        new(
            "CP1H", "CP1H", [], null,
            [.. CsCjAreas(CsCjBounds, verified: false, withEm: false, withLr: true)],
            [],
            Cp1CMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
            "CP1H manual pages not found: the CS/CJ bounds without EM, unverified"),
        new(
            "CS1", "CS1/CJ1/CJ2", ["CJ1", "CJ2", "CS/CJ", "CS1H", "CJ1H", "CJ1M", "CS1G", "CJ1G"], 0x30,
            [.. CsCjAreas(W342 + " p128 (4-3 C-mode address ranges) and section 5-2-2 (FINS I/O memory)", verified: true, withEm: true, withLr: true)],
            [],
            CsCjCMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
            "MM code: W342 p141 (4-3-30); ranges and commands: W342 sections 4 and 5"),
    ];

    private static PlcModelProfile Cp1e(string name, string display, string[] aliases, int lastDm) => new(
        name, display, aliases, null,
        [
            Rw(PlcArea.Cio, 0, 6143, CsCjBounds, false),
            Rw(PlcArea.Work, 0, 511, CsCjBounds, false),
            Rw(PlcArea.Holding, 0, 511, CsCjBounds, false),
            Ro(PlcArea.Auxiliary, 0, 447, CsCjBounds, false),
            Rw(PlcArea.Auxiliary, 448, 959, CsCjBounds, false),
            Rw(PlcArea.Timer, 0, 4095, CsCjBounds, false),
            Rw(PlcArea.Counter, 0, 4095, CsCjBounds, false),
            Rw(PlcArea.Dm, 0, lastDm, "W480 (CP1E) DM size; the page was not found", false),
        ],
        [],
        Cp2eCMode, supportsFins: true, sharesTimerCounterNumbers: false, TimerCounterCoding.BcdOrBinary,
        "W480 CP1E CPU Unit Software User's Manual (pages not found); C-mode list as the CP2E's (" + W614 + " p14-40), unverified for the CP1E");

    private static PlcAreaRange[] Cp1lLAreas() =>
    [
        .. CsCjAreas(CsCjBounds, verified: false, withEm: false, withLr: true).Where(r => r.Area != PlcArea.Dm),
        Rw(PlcArea.Dm, 0, 9999, NotFound, false),
        Rw(PlcArea.Dm, 32000, 32767, NotFound, false),
    ];

    private static PlcAreaRange[] Cqm1hAreas(bool withEm)
    {
        var areas = new List<PlcAreaRange>
        {
            Rw(PlcArea.Cio, 0, 252, Cqm1h + " p470 (QQ: IR/SR 0000–0255); WR limit as the CQM1", false),
            Ro(PlcArea.Cio, 253, 255, "as the CQM1 (" + CpmQ + " p369)", false),
            Rw(PlcArea.Link, 0, 63, Cqm1h + " p470 (QQ: LR 0000–0063)"),
            Rw(PlcArea.Holding, 0, 99, Cqm1h + " p470 (QQ: HR 0000–0099)"),
            Rw(PlcArea.Auxiliary, 0, 27, Cqm1h + " p470 (QQ: AR 0000–0027)"),
            Rw(PlcArea.Timer, 0, 511, Cqm1h + " p470 (QQ: TIM/CNT 0000–0511)"),
            Rw(PlcArea.Counter, 0, 511, Cqm1h + " p470 (QQ: TIM/CNT 0000–0511)"),
            Rw(PlcArea.Dm, 0, 6655, Cqm1h + " p470 (QQ: DM 0000–6655)"),
        };
        if (withEm)
        {
            areas.Add(Em(0, 6143, 1, Cqm1h + " p470 (QQ: EM 0000–6143, CPU61 only)"));
        }

        return [.. areas];
    }

    private static IEnumerable<PlcAreaRange> CsCjAreas(string source, bool verified, bool withEm, bool withLr)
    {
        yield return Rw(PlcArea.Cio, 0, 6143, source, verified);
        yield return Rw(PlcArea.Work, 0, 511, source, verified);
        yield return Rw(PlcArea.Holding, 0, 511, source, verified);
        yield return Ro(PlcArea.Auxiliary, 0, 447, source, verified);
        yield return Rw(PlcArea.Auxiliary, 448, 959, source, verified);
        yield return Rw(PlcArea.Timer, 0, 4095, source, verified);
        yield return Rw(PlcArea.Counter, 0, 4095, source, verified);
        yield return Rw(PlcArea.Dm, 0, 32767, source, verified);
        if (withEm)
        {
            // Which banks exist depends on the CPU; a missing bank is refused by the PLC with an end code, not read as 0000.
            yield return Em(0, 32767, PlcAreaInfo.EmBankCount, source, verified);
        }

        if (withLr)
        {
            yield return Rw(PlcArea.Link, 0, 199, verified ? W342 + " p128 (RL/WL: LR 0000–0199 = CIO 1000–1199)" : source, verified);
        }
    }

    private static Dictionary<byte, PlcModelProfile> BuildByModelCode()
    {
        var byCode = new Dictionary<byte, PlcModelProfile>();
        foreach (var group in Profiles.Where(p => p.ModelCode is not null).GroupBy(p => p.ModelCode!.Value))
        {
            var members = group.ToArray();
            byCode[group.Key] = members.Length == 1 ? members[0] : Common(group.Key, members);
        }

        return byCode;
    }

    // The part of several profiles that each of them has: what is safe to read on a PLC known only by its MM code.
    private static PlcModelProfile Common(byte code, PlcModelProfile[] members)
    {
        IEnumerable<PlcAreaRange> areas = members[0].Areas;
        foreach (var other in members.Skip(1))
        {
            areas = Intersect(areas.ToArray(), other.Areas);
        }

        var commands = members.Select(m => (IEnumerable<CModeCommandRow>)m.CModeCommands).Aggregate((a, b) => a.Intersect(b)).ToArray();
        var names = string.Join(", ", members.Select(m => m.DisplayName));
        var first = members[0];
        return new PlcModelProfile(
            $"MM{code:X2}",
            $"PLC answering MM {code:X2} ({names}: only what all of them have)",
            [],
            code,
            [.. areas],
            [],
            commands,
            members.All(m => m.SupportsFins),
            first.SharesTimerCounterNumbers,
            members.Any(m => m.TimerCounterCoding == TimerCounterCoding.BcdOrBinary) ? TimerCounterCoding.BcdOrBinary : TimerCounterCoding.Bcd,
            "the ranges and commands common to " + names);
    }

    private static IEnumerable<PlcAreaRange> Intersect(PlcAreaRange[] left, IReadOnlyList<PlcAreaRange> right)
    {
        foreach (var a in left)
        {
            foreach (var b in right)
            {
                if (a.Area != b.Area)
                {
                    continue;
                }

                int first = Math.Max(a.First, b.First), last = Math.Min(a.Last, b.Last);
                if (first > last)
                {
                    continue;
                }

                yield return new PlcAreaRange(
                    a.Area, first, last, a.Writable && b.Writable, "common part", a.Verified && b.Verified, Math.Min(a.BankCount, b.BankCount));
            }
        }
    }

    private static CModeCommandRow Read(CModeArea area) => AreaReadCommand.Rows[(int)area];

    private static CModeCommandRow Write(CModeArea area) => AreaWriteCommand.Rows[(int)area]!;

    private static PlcAreaRange Rw(PlcArea area, int first, int last, string source, bool verified = true) =>
        new(area, first, last, writable: true, source, verified);

    private static PlcAreaRange Ro(PlcArea area, int first, int last, string source, bool verified = true) =>
        new(area, first, last, writable: false, source, verified);

    private static PlcAreaRange Em(int first, int last, int banks, string source, bool verified = true) =>
        new(PlcArea.Em, first, last, writable: true, source, verified, banks);
}
