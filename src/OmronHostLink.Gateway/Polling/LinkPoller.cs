using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Planning;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// Polls one link: its <see cref="HostLinkClient"/> and one planned <c>WatchAsync</c> per unit and interval (a scan
/// class): the groups and tag-file rows of that unit and interval are read together, in the fewest commands the
/// planner finds (area reads spanning neighbours, QQ where the unit's model has it), each group's words in one command.
/// The watch's events become each group's values, quality and logs, and the tag sink's calls. The client's gate takes
/// waiting reads in turn, so the scan classes (and writes) share the link and none starves.
/// </summary>
/// <remarks>
/// A PLC unit that stops answering is reported once; while it is down one of its scan classes tries it with the watch's
/// capped backoff and the others wait, and it is reported again when it answers. After the link's
/// <c>Demotion:After</c> silent polls in a row that scan class's watch demotes the unit: no read for
/// <c>Demotion:Period</c>, then one presence probe. When the PLC answers a scan class's read with an error, each of its
/// groups is read once on its own: those that fail alone are read on their own (each reporting its failure) until they
/// read again, and the others together.
/// </remarks>
/// <param name="name">The link's name.</param>
/// <param name="options">The link's validated options.</param>
/// <param name="client">Gives the link's client.</param>
/// <param name="logger">The worker's log.</param>
/// <param name="time">The clock of intervals, backoff and timestamps.</param>
/// <param name="sink">Receives every poll's outcome, the link's state and its scan classes' plans and cycles.</param>
internal sealed class LinkPoller(string name, LinkOptions options, Func<HostLinkClient> client, ILogger logger, TimeProvider time, ITagOutput sink)
{
    private readonly object _lock = new();
    private readonly Dictionary<int, UnitHealth> _units = new();
    private readonly List<ScanRun> _runs = new();
    private List<PollGroup> _groups = [];
    private List<PollScan> _classes = [];
    private bool _planLogged;
    private long _polls;
    private long _failures;
    private CancellationToken _stopping;
    private long _started;
    private HostLinkClient? _plc;

    /// <summary>What a scan's watch asks its loop to do when it stops reading.</summary>
    private enum Outcome
    {
        /// <summary>The PLC answered a read of several groups with an error: find the groups that fail alone.</summary>
        Split,

        /// <summary>A group read on its own reads again: back to its scan class.</summary>
        Rejoin,
    }

    /// <summary>Polls until <paramref name="stoppingToken"/> is cancelled; nothing a PLC or a line does ends it.</summary>
    public async Task RunAsync(CancellationToken stoppingToken)
    {
        _stopping = stoppingToken;
        HostLinkClient plc;
        try
        {
            plc = client();
            _plc = plc;
            _groups = options.Groups.Select(g => new PollGroup(g.Key, g.Value, plc.Unit(g.Value.Unit), options.WordOrder)).ToList();
        }
        catch (Exception e)
        {
            GatewayLog.LinkFailed(logger, e, name);
            sink.LinkChanged(name, LinkState.Offline, e.Message);
            return;
        }

        foreach (PollGroup g in _groups)
        {
            _units.TryAdd(g.UnitNumber, new UnitHealth());
        }

        // One scan class per unit and interval, in the order their first groups are configured.
        _classes = PollScan.Classes(_groups, plc);

        sink.LinkOpened(name, plc);
        GatewayLog.LinkStarted(logger, name, _groups.Count, plc.Description);
        lock (_lock)
        {
            _started = time.GetTimestamp();
            foreach (PollScan scan in _classes)
            {
                Start(scan);
            }
        }

        try
        {
            await Task.Delay(Timeout.Infinite, stoppingToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            // Stopping.
        }

        Task[] running;
        lock (_lock)
        {
            running = _runs.Select(r => r.Task).ToArray();
        }

        await Task.WhenAll(running).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        sink.LinkChanged(name, LinkState.Offline);
        GatewayLog.LinkStopped(logger, name, _polls, _failures);
    }

    /// <summary>Starts polling <paramref name="scan"/> (under the lock).</summary>
    private void Start(PollScan scan)
    {
        var run = new ScanRun(scan, CancellationTokenSource.CreateLinkedTokenSource(_stopping));
        _runs.Add(run);
        run.Task = Task.Run(() => PollAsync(run));
    }

    /// <summary>Stops polling <paramref name="scan"/> (under the lock): it is replaced by others.</summary>
    private void Retire(PollScan scan)
    {
        ScanRun run = _runs.Single(r => r.Scan == scan);
        _runs.Remove(run);
        run.Stop.Cancel();
        _ = run.Task.ContinueWith(_ => run.Stop.Dispose(), CancellationToken.None, TaskContinuationOptions.ExecuteSynchronously, TaskScheduler.Default);
    }

    private async Task PollAsync(ScanRun run)
    {
        PollScan scan = run.Scan;
        var watch = new WatchOptions
        {
            Interval = scan.Interval,
            RetryInterval = options.Backoff.Initial,
            MaxRetryInterval = options.Backoff.Max,
            ReportEveryCycle = true,
            ReportPlans = true,
            DemoteAfter = options.Demotion.After,
            DemotionPeriod = options.Demotion.Period,
            TimeProvider = time,

            // Each class reads at once, then on its phase from the link's start, however late its watch starts, so
            // that the classes come due on the shared line in a fixed order (LineSchedule); a scan that replaces
            // another keeps its schedule.
            ScheduleStart = _started + (long)(LineSchedule.Anchor(scan.Phase, scan.Interval).Ticks * (double)time.TimestampFrequency / TimeSpan.TicksPerSecond),
        };
        CancellationToken token = run.Stop.Token;
        try
        {
            while (!token.IsCancellationRequested)
            {
                Outcome? outcome;
                try
                {
                    outcome = await WatchAsync(scan, watch, token).ConfigureAwait(false);
                }
                catch (ArgumentException e) when (!token.IsCancellationRequested)
                {
                    // Refused before the wire (a tag beyond the unit's model): as an error the PLC would answer.
                    lock (_lock)
                    {
                        _failures++;
                        outcome = Answered(scan, e.Message);
                    }

                    if (outcome is null)
                    {
                        await Task.Delay(options.Backoff.Max, time, token).ConfigureAwait(false);
                        continue;
                    }
                }
                catch (Exception e) when (!token.IsCancellationRequested)
                {
                    // A watch ends only on a bug (nothing a PLC or a line does): report it and watch again after an interval.
                    lock (_lock)
                    {
                        _failures++;
                        if (scan.Failure != e.Message)
                        {
                            scan.Failure = e.Message;
                            GatewayLog.GroupCrashed(logger, e, name, scan.Name, scan.UnitNumber, scan.Groups[0].AddressText);
                        }

                        foreach (PollGroup g in scan.Groups)
                        {
                            sink.TagChanged(g.Change(name, TagQuality.Stale, time.GetUtcNow(), e.Message));
                        }
                    }

                    await Task.Delay(scan.Interval, time, token).ConfigureAwait(false);
                    continue;
                }

                switch (outcome)
                {
                    case Outcome.Split:
                        await SplitAsync(scan, token).ConfigureAwait(false);
                        return;
                    case Outcome.Rejoin:
                        Rejoin(scan);
                        return;
                }
            }
        }
        catch (OperationCanceledException) when (token.IsCancellationRequested)
        {
            // Stopping, or replaced by other scans.
        }
    }

    /// <summary>Reads <paramref name="scan"/> with one watch until it is stopped or asks for something else.</summary>
    private async Task<Outcome?> WatchAsync(PollScan scan, WatchOptions watch, CancellationToken token)
    {
        IAsyncEnumerator<WatchEvent> events = scan.Unit.WatchAsync(scan.Tags, watch, token).GetAsyncEnumerator(token);
        Task<bool> next = events.MoveNextAsync().AsTask();
        try
        {
            while (await next.ConfigureAwait(false))
            {
                WatchEvent e = events.Current;
                if (e.Kind != WatchEventKind.Polled)
                {
                    // Not asking for the next event holds the watch: a scan waits here while another probes its unit.
                    (Task? unitAnswers, Outcome? stop) = Handle(scan, e);
                    if (stop is not null)
                    {
                        return stop;
                    }

                    if (unitAnswers is not null)
                    {
                        await unitAnswers.WaitAsync(token).ConfigureAwait(false);
                    }

                    next = events.MoveNextAsync().AsTask();
                    continue;
                }

                // Queue for the next read (past an overrun report, which comes first) before logging and publishing
                // this one: the scan is back at the link's gate as soon as its read is done, so on a busy link the
                // scans keep their turns whatever their handling costs. A group read on its own that reads again goes
                // back to its class instead.
                bool rejoin = scan.Isolated;
                if (!rejoin)
                {
                    next = events.MoveNextAsync().AsTask();
                }

                WatchEvent? overrun = null;
                if (!rejoin && next.IsCompletedSuccessfully && next.Result && events.Current.Kind == WatchEventKind.Overrun)
                {
                    overrun = events.Current;
                    next = events.MoveNextAsync().AsTask();
                }

                (_, Outcome? outcome) = Handle(scan, e, overrun is not null); // Never holds back: the unit answered.
                if (overrun is not null)
                {
                    _ = Handle(scan, overrun);
                }

                if (rejoin || outcome is not null)
                {
                    return outcome ?? Outcome.Rejoin;
                }
            }

            return null;
        }
        finally
        {
            // A read may still be under way (when handling failed, or the scan stops); the watch can only be closed after it.
            if (!next.IsCompleted)
            {
                // A scan that stops reading (split, rejoin) does not wait for its next cycle's interval.
                await ((Task)next).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
            }

            await events.DisposeAsync().ConfigureAwait(false);
        }
    }

    /// <summary>
    /// Takes one event of a scan's watch; returns a task to wait for before the next when the scan must hold back, and
    /// what the scan must do instead of reading on.
    /// </summary>
    private (Task? Wait, Outcome? Outcome) Handle(PollScan scan, WatchEvent e, bool overrunFollows = false)
    {
        lock (_lock)
        {
            switch (e.Kind)
            {
                case WatchEventKind.Changed:
                    (PollGroup group, int index) = scan.Owner(e.TagIndex);
                    group.Update(index, e);
                    return default;
                case WatchEventKind.Polled:
                    _polls++;
                    Cycled(scan, e.Duration, overrunFollows);
                    Read(scan);
                    return default;
                case WatchEventKind.Planned:
                    Planned(scan, e.Plan!);
                    return default;
                case WatchEventKind.Outage or WatchEventKind.RetryFailed:
                    _polls++;
                    _failures++;
                    return Failed(scan, e.Exception!, e.RetryDelay);
                case WatchEventKind.Demoted:
                    if (!ReferenceEquals(e.Exception, _units[scan.UnitNumber].LastFailure))
                    {
                        // The silent poll that demotes is a failed attempt like the others (unless its outage was just reported).
                        _polls++;
                        _failures++;
                        _ = Failed(scan, e.Exception!, e.RetryDelay);
                    }

                    Demoted(scan, e);
                    return default;
                case WatchEventKind.Overrun:
                    Overran(scan, e.Duration);
                    return default;
                default:
                    return default; // Resumed: the cycle's changes and Polled follow.
            }
        }
    }

    private void Read(PollScan scan)
    {
        UnitAnswered(scan.UnitNumber);
        if (scan.Failure is not null && !scan.Isolated)
        {
            scan.Failure = null;
        }

        foreach (PollGroup group in scan.Groups)
        {
            Publish(group);
        }
    }

    /// <summary>Logs and publishes a group's values just read.</summary>
    private void Publish(PollGroup group)
    {
        string values;
        try
        {
            values = group.Format();
        }
        catch (FormatException e)
        {
            _failures++;
            GroupFailed(group, e.Message);
            return;
        }

        if (group.Failure is not null)
        {
            group.Failure = null;
            GatewayLog.GroupRecovered(logger, name, group.Name, group.UnitNumber, group.AddressText);
        }

        sink.TagChanged(group.Change(name, TagQuality.Good, time.GetUtcNow()));
        if (group.Mode == PollLogMode.EveryPoll || group.LastLogged != values)
        {
            group.LastLogged = values;
            GatewayLog.Values(logger, name, group.Name, group.UnitNumber, group.AddressText, values);
        }
    }

    private (Task? Wait, Outcome? Outcome) Failed(PollScan scan, Exception e, TimeSpan retryDelay)
    {
        string? reason = e switch
        {
            HostLinkTimeoutException or TimeoutException or OperationCanceledException => "timeout",
            HostLinkConnectionException or IOException => "connection",
            HostLinkFrameException => "damaged answers",
            _ => null,
        };
        if (reason is null)
        {
            // The PLC answered (an end code): the unit is up, some of the scan's groups are not.
            UnitAnswered(scan.UnitNumber);
            return (null, Answered(scan, e.Message));
        }

        UnitHealth unit = _units[scan.UnitNumber];
        unit.LastFailure = e;
        if (!unit.Down)
        {
            unit.Down = true;
            unit.Since = time.GetTimestamp();
            unit.Attempts = 1;
            unit.Prober = scan;
            unit.RetryDelay = retryDelay;
            unit.Answers = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            GatewayLog.UnitDown(logger, name, scan.UnitNumber, reason, e.Message, retryDelay.TotalSeconds, options.Backoff.Max.TotalSeconds);

            // Every tag of the unit, not only the ones that failed: none of them can be read now.
            foreach (PollGroup g in _groups.Where(g => g.UnitNumber == scan.UnitNumber))
            {
                sink.TagChanged(g.Change(name, TagQuality.CommError, time.GetUtcNow(), e.Message));
            }

            sink.UnitChanged(name, scan.UnitNumber, UnitState.CommError, e.Message);
            sink.LinkChanged(name, LinkState.CommError, e.Message);
            return default;
        }

        unit.Attempts++;
        if (unit.Prober == scan)
        {
            unit.RetryDelay = retryDelay;
        }

        GatewayLog.UnitStillDown(logger, name, scan.UnitNumber, reason, e.Message, unit.RetryDelay.TotalSeconds);
        return (unit.Prober == scan ? null : unit.Answers.Task, null);
    }

    /// <summary>
    /// The PLC answered the scan's read with an error (or the model refused it before the wire): a scan of several
    /// groups is split to find which fail; a single group reports its failure and is tried again by its watch.
    /// </summary>
    private Outcome? Answered(PollScan scan, string message)
    {
        if (scan.Groups.Count > 1)
        {
            return Outcome.Split;
        }

        GroupFailed(scan.Groups[0], message);
        return null;
    }

    /// <summary>The scan's watch demoted its unit: every tag of the unit is comm-error, and the unit is reported demoted.</summary>
    private void Demoted(PollScan scan, WatchEvent e)
    {
        UnitHealth unit = _units[scan.UnitNumber];
        if (unit.Demoted)
        {
            return;
        }

        unit.Demoted = true;
        GatewayLog.UnitDemoted(logger, name, scan.UnitNumber, options.Demotion.After, e.RetryDelay.TotalSeconds, e.Exception!.Message);
        foreach (PollGroup g in _groups.Where(g => g.UnitNumber == scan.UnitNumber))
        {
            sink.TagChanged(g.Change(name, TagQuality.CommError, time.GetUtcNow(), e.Exception.Message));
        }

        sink.UnitChanged(name, scan.UnitNumber, UnitState.Demoted, e.Exception.Message);
    }

    private void GroupFailed(PollGroup group, string message)
    {
        if (group.Failure != message)
        {
            group.Failure = message;
            GatewayLog.GroupFailed(logger, name, group.Name, group.UnitNumber, group.AddressText, message);
        }

        sink.TagChanged(group.Change(name, TagQuality.Stale, time.GetUtcNow(), message));
    }

    private void UnitAnswered(int unitNumber)
    {
        UnitHealth unit = _units[unitNumber];
        if (!unit.Down)
        {
            return;
        }

        if (unit.Demoted)
        {
            GatewayLog.UnitRestored(logger, name, unitNumber, time.GetElapsedTime(unit.Since).TotalSeconds);
        }
        else
        {
            GatewayLog.UnitResumed(logger, name, unitNumber, time.GetElapsedTime(unit.Since).TotalSeconds, unit.Attempts);
        }

        unit.Down = false;
        unit.Demoted = false;
        sink.UnitChanged(name, unitNumber, UnitState.Online);
        unit.Prober = null;
        unit.Answers.TrySetResult();
        if (!_units.Values.Any(u => u.Down))
        {
            sink.LinkChanged(name, LinkState.Online);
        }
    }

    // ---- Scan classes: plans, cycles, splits ----

    /// <summary>A scan's watch (re)planned its reads: logged with the link's plan at start, on its own after.</summary>
    private void Planned(PollScan scan, ReadPlan plan)
    {
        bool again = scan.Plan is not null;
        bool compoundDropped = again && UsesCompound(scan.Plan!) && !UsesCompound(plan);
        scan.Plan = plan;

        // A plan changes every class's expected cycle on the shared line: each is reported again.
        ScanPlan[] reports = Reports();
        foreach (ScanPlan each in reports)
        {
            (sink as IScanOutput)?.ScanPlanned(each);
        }

        if (_planLogged)
        {
            // A later plan: a unit's model became known (MM), QQ was refused, or the scan class was split or joined.
            if (!scan.Isolated)
            {
                LogScan(ReportOf(reports, scan), compoundDropped ? " (planned again: the unit answered QQ with an error, and is read by area from now on)" : again ? " (planned again)" : "");
            }

            return;
        }

        LogPlanOnceComplete();
    }

    private static bool UsesCompound(ReadPlan plan) => plan.Reads.Any(r => r.Kind == PlannedReadKind.CModeCompound);

    /// <summary>Logs the link's plan once every scan class has its first.</summary>
    private void LogPlanOnceComplete()
    {
        if (!_planLogged && _classes.All(c => c.Plan is not null))
        {
            _planLogged = true;
            LogPlan();
        }
    }

    /// <summary>
    /// The link's plan at start: a line for the link, one for each scan class, and what will not fit. A scan class whose
    /// unit is asked its model (MM) before QQ is used is judged by its plan with QQ, which it reads with once the unit
    /// names a model that has it, on the line as it will be then.
    /// </summary>
    private void LogPlan()
    {
        ScanPlan[] plans = Reports();
        ReadPlan?[] pending = _classes.Select(c => ScanPlanReport.PendingCompound(c, options)).ToArray();
        ScanPlan[] expected = Reports(c => ScanPlanReport.PendingCompound(c, options));
        double load = expected.Sum(Load);
        GatewayLog.LinkPlanned(logger, name, _groups.Count, plans.Length, Line(), expected.Sum(p => p.Reads), expected.Sum(p => p.Characters), load);
        for (int i = 0; i < plans.Length; i++)
        {
            string note = pending[i] is { } qq
                ? $"; once the unit names its model (MM), and where that model has QQ: {qq}, {PollScan.Durations(expected[i].EstimatedCycle)} a cycle"
                : "";
            LogScan(plans[i], note, expected[i]);
        }

        if (load > 1 && plans.Length > 1)
        {
            string detail = string.Join("; ", expected.Select(p => $"unit {p.Unit} every {PollScan.Durations(p.Interval)}: {PollScan.Durations(p.LineTime)} on the line a cycle, {Load(p):P0}"));
            GatewayLog.LinkOverloaded(logger, name, load, detail);
        }
    }

    /// <summary>Logs a scan class's plan, and warns when <paramref name="judged"/> (the plan, or the one it will read with) cannot keep the interval.</summary>
    private void LogScan(ScanPlan plan, string note, ScanPlan? judged = null)
    {
        GatewayLog.ScanPlanned(logger, name, plan.Unit, PollScan.Durations(plan.Interval), plan.Tags, plan.Description, plan.EstimatedCycle.TotalMilliseconds, plan.LineTime.TotalMilliseconds, note);
        judged ??= plan;
        if (judged.EstimatedCycle > judged.Interval)
        {
            GatewayLog.ScanCannotFit(logger, name, judged.Unit, judged.Tags, PollScan.Durations(judged.Interval), judged.EstimatedCycle.TotalMilliseconds, judged.LineTime.TotalMilliseconds, judged.Description == plan.Description ? plan.Description : "with QQ");
        }
    }

    private TimeSpan Gap => options.Client.SendInterval ?? TimeSpan.Zero;

    /// <summary>
    /// The scan classes' plans as the outputs see them: each class's own reads, and those of its groups read on their
    /// own after a failure; its own time on the line (the reads' characters at the line's speed and the send interval
    /// before each); and the cycle it can expect on the line it shares with the link's other classes
    /// (<see cref="LineSchedule"/>). With <paramref name="instead"/>, a class is reckoned with the plan it gives (the
    /// one it will read with) where it gives one.
    /// </summary>
    private ScanPlan[] Reports(Func<PollScan, ReadPlan?>? instead = null)
    {
        PollScan[] classes = _classes.Where(c => c.Plan is not null).ToArray();
        var parts = new List<(PollScan Part, ReadPlan Plan)[]>();
        foreach (PollScan scan in classes)
        {
            ReadPlan own = instead?.Invoke(scan) ?? scan.Plan!;
            parts.Add(_runs.Select(r => r.Scan)
                .Where(s => s != scan && s.Plan is not null && s.UnitNumber == scan.UnitNumber && s.Interval == scan.Interval)
                .Select(s => (s, s.Plan!))
                .Prepend((scan, own))
                .ToArray());
        }

        LineSchedule.Watch[] watches = parts.SelectMany(p => p).Select(p => p.Part.OnLine(p.Plan, Gap)).ToArray();
        TimeSpan[] cycles = LineSchedule.ExpectedCycles(watches);
        var reports = new ScanPlan[classes.Length];
        int w = 0;
        for (int i = 0; i < classes.Length; i++)
        {
            (PollScan Part, ReadPlan Plan)[] own = parts[i];
            TimeSpan lineTime = TimeSpan.FromTicks(watches.Skip(w).Take(own.Length).Sum(p => p.LineTime.Ticks));
            reports[i] = new ScanPlan(
                name,
                classes[i].UnitNumber,
                classes[i].Interval,
                own.Sum(p => p.Part.Groups.Count),
                own.Sum(p => p.Plan.TransactionCount),
                own.Sum(p => p.Plan.Characters),
                lineTime,
                cycles[w],
                string.Join(" + ", own.Select(p => p.Plan.ToString())));
            w += own.Length;
        }

        return reports;
    }

    /// <summary>The report of <paramref name="scan"/>'s class (a part read on its own belongs to its unit's class at its interval).</summary>
    private static ScanPlan ReportOf(ScanPlan[] reports, PollScan scan)
        => reports.First(r => r.Unit == scan.UnitNumber && r.Interval == scan.Interval);

    /// <summary>The class's share of the line's time.</summary>
    private static double Load(ScanPlan plan) => plan.LineTime.TotalSeconds / plan.Interval.TotalSeconds;

    private string Line() => $"{_plc!.LineTiming.BaudRate} bps";

    /// <summary>A cycle of the scan read every tag in <paramref name="duration"/>.</summary>
    private void Cycled(PollScan scan, TimeSpan duration, bool overrunFollows)
    {
        scan.Cycled(duration);
        if (scan.Isolated)
        {
            return;
        }

        (sink as IScanOutput)?.ScanCycled(new ScanCycle(name, scan.UnitNumber, scan.Interval, duration, overrunFollows));
        if (!overrunFollows && scan.OnTime())
        {
            GatewayLog.ScanKeepsUp(logger, name, scan.UnitNumber, PollScan.Durations(scan.Interval));
        }
    }

    /// <summary>The scan's next cycle started late: <paramref name="period"/> after the one before.</summary>
    private void Overran(PollScan scan, TimeSpan period)
    {
        long skipped = (period.Ticks / scan.Interval.Ticks) - 1;
        if (skipped > 0 && !_units[scan.UnitNumber].Down)
        {
            GatewayLog.TicksSkipped(logger, name, scan.Name, skipped);
        }

        if (scan.Overran(period) is { } sustained && !scan.Isolated)
        {
            ScanPlan plan = ReportOf(Reports(), scan);
            GatewayLog.ScanOverrun(logger, name, scan.UnitNumber, plan.Tags, PollScan.Durations(scan.Interval), sustained.TotalMilliseconds, 10, plan.EstimatedCycle.TotalMilliseconds, scan.LastCycle.TotalMilliseconds);
        }
    }

    /// <summary>
    /// The PLC answered a read of several groups with an error: each group is read once on its own. Those that fail
    /// alone are read on their own from now on (each reporting its failure) until they read again; the others are read
    /// together. Values read meanwhile are published.
    /// </summary>
    private async Task SplitAsync(PollScan scan, CancellationToken token)
    {
        var failed = new List<PollGroup>();
        foreach (PollGroup group in scan.Groups)
        {
            try
            {
                PlcTagValue[] values = await group.Unit.ReadTagsAsync(group.Tags, token).ConfigureAwait(false);
                lock (_lock)
                {
                    group.Read(values);
                    Publish(group);
                }
            }
            catch (Exception e) when (e is HostLinkEndCodeException or FinsEndCodeException or ArgumentException or NotSupportedException or FormatException)
            {
                lock (_lock)
                {
                    _failures++;
                    GroupFailed(group, e.Message);
                    failed.Add(group);
                }
            }
            catch (Exception e) when (e is HostLinkException or IOException or TimeoutException && !token.IsCancellationRequested)
            {
                // The unit went away meanwhile: the scan reads on as it was, and its watch reports the outage.
                failed.Clear();
                break;
            }
        }

        if (failed.Count == 0)
        {
            // Every group read alone (and was published): the scan reads on as it was from its next cycle, so that a
            // failure of the reads together that lasts costs the line its one try and these reads an interval.
            await Task.Delay(scan.Interval, time, token).ConfigureAwait(false);
        }

        lock (_lock)
        {
            if (token.IsCancellationRequested)
            {
                return;
            }

            Retire(scan);
            if (failed.Count == 0)
            {
                var again = new PollScan(scan.Unit, scan.Interval, scan.Groups, scan.Isolated) { Phase = scan.Phase };
                Replace(scan, again);
                Start(again);
                return;
            }

            GatewayLog.ScanSplit(logger, name, scan.UnitNumber, PollScan.Durations(scan.Interval), failed.Count, scan.Groups.Count, string.Join(", ", failed.Select(g => g.Name)));
            if (failed.Count < scan.Groups.Count)
            {
                var rest = new PollScan(scan.Unit, scan.Interval, scan.Groups.Except(failed).ToList()) { Phase = scan.Phase };
                Replace(scan, rest);
                Start(rest);
            }
            else
            {
                Replace(scan, null);
            }

            foreach (PollGroup group in failed)
            {
                Start(new PollScan(scan.Unit, scan.Interval, [group], isolated: true) { Phase = scan.Phase });
            }
        }
    }

    /// <summary>A group read on its own reads again: its class is read with it again.</summary>
    private void Rejoin(PollScan isolated)
    {
        lock (_lock)
        {
            if (_stopping.IsCancellationRequested)
            {
                return;
            }

            PollGroup group = isolated.Groups[0];
            Retire(isolated);
            GatewayLog.ScanRejoined(logger, name, group.Name, isolated.UnitNumber, PollScan.Durations(isolated.Interval));
            PollScan? owner = _runs.Select(r => r.Scan).FirstOrDefault(s => !s.Isolated && s.UnitNumber == isolated.UnitNumber && s.Interval == isolated.Interval);
            IEnumerable<PollGroup> members = owner is null ? [group] : owner.Groups.Append(group);

            // Configuration order, as the class was first planned.
            var joined = new PollScan(isolated.Unit, isolated.Interval, _groups.Where(members.Contains).ToList()) { Phase = owner?.Phase ?? isolated.Phase };
            if (owner is not null)
            {
                Retire(owner);
            }

            Replace(owner, joined);
            Start(joined);
        }
    }

    /// <summary>
    /// The class scan <paramref name="old"/> is now <paramref name="replacement"/> (null: every group of the class is
    /// read on its own), for the start log and the unit's prober; with no old one, the class is added.
    /// </summary>
    private void Replace(PollScan? old, PollScan? replacement)
    {
        int index = old is null ? -1 : _classes.IndexOf(old);
        if (index >= 0 && replacement is not null)
        {
            _classes[index] = replacement;
        }
        else if (index >= 0)
        {
            _classes.RemoveAt(index);
            LogPlanOnceComplete();
        }
        else if (replacement is not null && !replacement.Isolated)
        {
            _classes.Add(replacement);
        }

        foreach (UnitHealth unit in _units.Values.Where(u => old is not null && u.Prober == old))
        {
            unit.Prober = replacement;
        }
    }

    /// <summary>A scan being polled, and what stops it.</summary>
    private sealed class ScanRun(PollScan scan, CancellationTokenSource stop)
    {
        public PollScan Scan { get; } = scan;

        public CancellationTokenSource Stop { get; } = stop;

        public Task Task { get; set; } = Task.CompletedTask;
    }

    /// <summary>Whether a PLC on the link answers; while it does not, which scan probes it and what the others wait for.</summary>
    private sealed class UnitHealth
    {
        public bool Down { get; set; }

        public bool Demoted { get; set; }

        /// <summary>The failure last reported for the unit (an outage and the demotion it causes carry the same one).</summary>
        public Exception? LastFailure { get; set; }

        public long Since { get; set; }

        public int Attempts { get; set; }

        public PollScan? Prober { get; set; }

        public TimeSpan RetryDelay { get; set; }

        public TaskCompletionSource Answers { get; set; } = new();
    }
}
