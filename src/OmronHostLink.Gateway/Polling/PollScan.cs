using System.Globalization;
using OmronHostLink.Planning;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// One planned watch: the poll groups of one unit read at one interval (a scan class), their tags read together with
/// the fewest commands the planner finds (each group's words in one command, one snapshot). Maps the watch's tags back
/// to the groups, and keeps the plan in force and the cycle times measured.
/// </summary>
internal sealed class PollScan
{
    private readonly (PollGroup Group, int Index)[] _owners;
    private int _overrunsInARow;
    private int _onTimeInARow;
    private TimeSpan _overrunPeriods;

    /// <summary>A scan of <paramref name="groups"/>, all of one unit and interval, through <paramref name="unit"/>.</summary>
    public PollScan(HostLinkUnit unit, TimeSpan interval, IReadOnlyList<PollGroup> groups, bool isolated = false)
    {
        Unit = unit;
        Interval = interval;
        Groups = groups;
        Isolated = isolated;
        _owners = groups.SelectMany(g => Enumerable.Range(0, g.Tags.Count).Select(i => (g, i))).ToArray();
        Tags = groups.SelectMany(g => g.Tags).ToArray();
    }

    /// <summary>
    /// One scan class per unit and interval, in the order their first groups are configured, each on the phase of its
    /// place (<see cref="LineSchedule.Phases"/>).
    /// </summary>
    public static List<PollScan> Classes(IEnumerable<PollGroup> groups, HostLinkUnit client)
    {
        var classes = groups.GroupBy(g => (g.UnitNumber, g.Interval)).ToList();
        TimeSpan[] phases = LineSchedule.Phases(classes.Select(c => c.Key.Interval).ToArray());
        return classes.Select((c, i) => new PollScan(client.Unit(c.Key.UnitNumber), c.Key.Interval, c.ToList()) { Phase = phases[i] }).ToList();
    }

    /// <summary>The unit's view on the link's client.</summary>
    public HostLinkUnit Unit { get; }

    /// <summary>The unit number.</summary>
    public int UnitNumber => Unit.UnitNumber;

    /// <summary>The scan class's interval.</summary>
    public TimeSpan Interval { get; }

    /// <summary>
    /// Where the scan's schedule lies after the link's start: its class's phase on the line. A scan that replaces
    /// another (a split or a rejoin) keeps the phase of its class: its first cycle starts at once, the next on the
    /// class's schedule.
    /// </summary>
    public TimeSpan Phase { get; init; }

    /// <summary>The scan on its line's schedule, reading with <paramref name="plan"/> and <paramref name="gap"/> before each command.</summary>
    public LineSchedule.Watch OnLine(ReadPlan plan, TimeSpan gap) => new(Interval, LineSchedule.Reads(plan, gap), Phase);

    /// <summary>The groups read, in configuration order.</summary>
    public IReadOnlyList<PollGroup> Groups { get; }

    /// <summary>Whether this is one group taken out of its scan class because it failed alone (read on its own until it reads again).</summary>
    public bool Isolated { get; }

    /// <summary>Every group's tags, in order: what the watch reads.</summary>
    public PlcTag[] Tags { get; }

    /// <summary>What the log calls it: <c>unit 0 every 1 s</c>, or the group's name for a group read on its own.</summary>
    public string Name => !Isolated
        ? string.Create(CultureInfo.InvariantCulture, $"unit {UnitNumber} every {Durations(Interval)}")
        : Groups[0].Name;

    /// <summary>The plan the watch reads with (from its <see cref="WatchEventKind.Planned"/> events); null before the first.</summary>
    public ReadPlan? Plan { get; set; }

    /// <summary>The failure last reported for the scan's groups while the unit answered (a scan of several groups is split on one).</summary>
    public string? Failure { get; set; }

    /// <summary>Cycles read.</summary>
    public long Cycles { get; private set; }

    /// <summary>Cycles that ended later than the next was due.</summary>
    public long Overruns { get; private set; }

    /// <summary>The last cycle's read time.</summary>
    public TimeSpan LastCycle { get; private set; }

    /// <summary>The read time of all cycles together.</summary>
    public TimeSpan TotalCycles { get; private set; }

    /// <summary>Whether a sustained overrun has been reported and has not ended.</summary>
    public bool OverrunReported { get; private set; }

    /// <summary>The group and the group's tag index a watch's tag index belongs to.</summary>
    public (PollGroup Group, int Index) Owner(int tagIndex) => _owners[tagIndex];

    /// <summary>A cycle read every tag in <paramref name="time"/>.</summary>
    public void Cycled(TimeSpan time)
    {
        Cycles++;
        LastCycle = time;
        TotalCycles += time;
    }

    /// <summary>
    /// The watch found the next cycle due before this one could start: the period was <paramref name="period"/>.
    /// Returns the average period of the overruns in a row once they are sustained (ten cycles and five seconds or
    /// more), the first time; null otherwise.
    /// </summary>
    public TimeSpan? Overran(TimeSpan period)
    {
        Overruns++;
        _overrunsInARow++;
        _onTimeInARow = 0;
        _overrunPeriods += period;
        if (!OverrunReported && _overrunsInARow >= SustainedCycles && _overrunPeriods >= SustainedTime)
        {
            OverrunReported = true;
            return _overrunPeriods / _overrunsInARow;
        }

        return null;
    }

    /// <summary>A cycle started on time. True once a reported overrun has ended (ten cycles on time in a row).</summary>
    public bool OnTime()
    {
        _overrunsInARow = 0;
        _overrunPeriods = TimeSpan.Zero;
        if (OverrunReported && ++_onTimeInARow >= SustainedCycles)
        {
            OverrunReported = false;
            _onTimeInARow = 0;
            return true;
        }

        return false;
    }

    /// <summary>A duration as the log writes it: <c>100 ms</c>, <c>1 s</c>, <c>2.5 s</c>.</summary>
    public static string Durations(TimeSpan time)
        => time < TimeSpan.FromSeconds(1)
            ? string.Create(CultureInfo.InvariantCulture, $"{time.TotalMilliseconds:0.#} ms")
            : string.Create(CultureInfo.InvariantCulture, $"{time.TotalSeconds:0.###} s");

    private const int SustainedCycles = 10;

    private static readonly TimeSpan SustainedTime = TimeSpan.FromSeconds(5);
}
