using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// Polls one link: its <see cref="HostLinkClient"/> and one <c>WatchAsync</c> per poll group, whose events become the
/// worker's logs and the tag sink's calls. The client's gate takes waiting reads in turn, so on a busy link the groups
/// alternate and none starves. A PLC unit that stops answering is reported once; while it is down one of its groups
/// tries it with the watch's capped backoff and the others wait, and it is reported again when it answers. After the
/// link's <c>Demotion:After</c> silent polls in a row that group's watch demotes the unit: no read for
/// <c>Demotion:Period</c>, then one presence probe, so a dead unit costs its neighbours on the line next to nothing.
/// </summary>
/// <param name="name">The link's name.</param>
/// <param name="options">The link's validated options.</param>
/// <param name="client">Gives the link's client.</param>
/// <param name="logger">The worker's log.</param>
/// <param name="time">The clock of intervals, backoff and timestamps.</param>
/// <param name="sink">Receives every poll's outcome and the link's state, or null.</param>
internal sealed class LinkPoller(string name, LinkOptions options, Func<HostLinkClient> client, ILogger logger, TimeProvider time, ITagOutput sink)
{
    private readonly object _lock = new();
    private readonly Dictionary<int, UnitHealth> _units = new();
    private List<PollGroup> _groups = [];
    private long _polls;
    private long _failures;

    /// <summary>Polls until <paramref name="stoppingToken"/> is cancelled; nothing a PLC or a line does ends it.</summary>
    public async Task RunAsync(CancellationToken stoppingToken)
    {
        HostLinkClient plc;
        try
        {
            plc = client();
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

        sink.LinkOpened(name, plc);
        GatewayLog.LinkStarted(logger, name, _groups.Count, plc.Description);
        try
        {
            // Started in configuration order: each first read queues at the gate before the next group's.
            await Task.WhenAll(_groups.Select(g => WatchAsync(g, stoppingToken))).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (stoppingToken.IsCancellationRequested)
        {
            // Stopping.
        }

        sink.LinkChanged(name, LinkState.Offline);
        GatewayLog.LinkStopped(logger, name, _polls, _failures);
    }

    private async Task WatchAsync(PollGroup group, CancellationToken stoppingToken)
    {
        var watch = new WatchOptions
        {
            Interval = group.Interval,
            RetryInterval = options.Backoff.Initial,
            MaxRetryInterval = options.Backoff.Max,
            ReportEveryCycle = true,
            DemoteAfter = options.Demotion.After,
            DemotionPeriod = options.Demotion.Period,
            TimeProvider = time,
        };
        while (true)
        {
            try
            {
                await WatchOnceAsync(group, watch, stoppingToken).ConfigureAwait(false);
            }
            catch (Exception e) when (!stoppingToken.IsCancellationRequested)
            {
                // A watch ends only on a bug (nothing a PLC or a line does): report it and watch again after an interval.
                lock (_lock)
                {
                    _failures++;
                    if (group.Failure != e.Message)
                    {
                        group.Failure = e.Message;
                        GatewayLog.GroupCrashed(logger, e, name, group.Name, group.UnitNumber, group.AddressText);
                    }

                    sink.TagChanged(group.Change(name, TagQuality.Stale, time.GetUtcNow(), e.Message));
                }

                await Task.Delay(group.Interval, time, stoppingToken).ConfigureAwait(false);
            }
        }
    }

    private async Task WatchOnceAsync(PollGroup group, WatchOptions watch, CancellationToken stoppingToken)
    {
        IAsyncEnumerator<WatchEvent> events = group.Unit.WatchAsync(group.Tags, watch, stoppingToken).GetAsyncEnumerator(stoppingToken);
        Task<bool> next = events.MoveNextAsync().AsTask();
        try
        {
            while (await next.ConfigureAwait(false))
            {
                WatchEvent e = events.Current;
                if (e.Kind != WatchEventKind.Polled)
                {
                    // Not asking for the next event holds the watch: a group waits here while another probes its unit.
                    if (Handle(group, e) is { } unitAnswers)
                    {
                        await unitAnswers.WaitAsync(stoppingToken).ConfigureAwait(false);
                    }

                    next = events.MoveNextAsync().AsTask();
                    continue;
                }

                // Queue for the next read (past an overrun report, which comes first) before logging and publishing
                // this one: the group is back at the link's gate as soon as its read is done, so on a busy link the
                // groups keep their turns whatever their handling costs.
                next = events.MoveNextAsync().AsTask();
                WatchEvent? overrun = null;
                if (next.IsCompletedSuccessfully && next.Result && events.Current.Kind == WatchEventKind.Overrun)
                {
                    overrun = events.Current;
                    next = events.MoveNextAsync().AsTask();
                }

                _ = Handle(group, e); // Never holds back: the unit answered.
                if (overrun is not null)
                {
                    _ = Handle(group, overrun);
                }
            }
        }
        finally
        {
            // A read may still be under way (when handling failed); the watch can only be closed after it.
            await ((Task)next).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
            await events.DisposeAsync().ConfigureAwait(false);
        }
    }

    /// <summary>Takes one event of a group's watch; returns a task to wait for before the next when the group must hold back.</summary>
    private Task? Handle(PollGroup group, WatchEvent e)
    {
        lock (_lock)
        {
            switch (e.Kind)
            {
                case WatchEventKind.Changed:
                    group.Update(e);
                    return null;
                case WatchEventKind.Polled:
                    _polls++;
                    Read(group);
                    return null;
                case WatchEventKind.Outage or WatchEventKind.RetryFailed:
                    _polls++;
                    _failures++;
                    return Failed(group, e.Exception!, e.RetryDelay);
                case WatchEventKind.Demoted:
                    if (!ReferenceEquals(e.Exception, _units[group.UnitNumber].LastFailure))
                    {
                        // The silent poll that demotes is a failed attempt like the others (unless its outage was just reported).
                        _polls++;
                        _failures++;
                        _ = Failed(group, e.Exception!, e.RetryDelay);
                    }

                    Demoted(group, e);
                    return null;
                case WatchEventKind.Overrun:
                    long skipped = (e.Duration.Ticks / group.Interval.Ticks) - 1;
                    if (skipped > 0 && !_units[group.UnitNumber].Down)
                    {
                        GatewayLog.TicksSkipped(logger, name, group.Name, skipped);
                    }

                    return null;
                default:
                    return null; // Resumed: the cycle's changes and Polled follow.
            }
        }
    }

    private void Read(PollGroup group)
    {
        UnitAnswered(group.UnitNumber);
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

    private Task? Failed(PollGroup group, Exception e, TimeSpan retryDelay)
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
            // The PLC answered (an end code): the unit is up, this group is not.
            UnitAnswered(group.UnitNumber);
            GroupFailed(group, e.Message);
            return null;
        }

        UnitHealth unit = _units[group.UnitNumber];
        unit.LastFailure = e;
        if (!unit.Down)
        {
            unit.Down = true;
            unit.Since = time.GetTimestamp();
            unit.Attempts = 1;
            unit.Prober = group;
            unit.RetryDelay = retryDelay;
            unit.Answers = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            GatewayLog.UnitDown(logger, name, group.UnitNumber, reason, e.Message, retryDelay.TotalSeconds, options.Backoff.Max.TotalSeconds);
            if (sink is not null)
            {
                // Every tag of the unit, not only the one that failed: none of them can be read now.
                foreach (PollGroup g in _groups.Where(g => g.UnitNumber == group.UnitNumber))
                {
                    sink.TagChanged(g.Change(name, TagQuality.CommError, time.GetUtcNow(), e.Message));
                }

                sink.UnitChanged(name, group.UnitNumber, UnitState.CommError, e.Message);
                sink.LinkChanged(name, LinkState.CommError, e.Message);
            }

            return null;
        }

        unit.Attempts++;
        if (unit.Prober == group)
        {
            unit.RetryDelay = retryDelay;
        }

        GatewayLog.UnitStillDown(logger, name, group.UnitNumber, reason, e.Message, unit.RetryDelay.TotalSeconds);
        return unit.Prober == group ? null : unit.Answers.Task;
    }

    /// <summary>The group's watch demoted its unit: every tag of the unit is comm-error, and the unit is reported demoted.</summary>
    private void Demoted(PollGroup group, WatchEvent e)
    {
        UnitHealth unit = _units[group.UnitNumber];
        if (unit.Demoted)
        {
            return;
        }

        unit.Demoted = true;
        GatewayLog.UnitDemoted(logger, name, group.UnitNumber, options.Demotion.After, e.RetryDelay.TotalSeconds, e.Exception!.Message);
        foreach (PollGroup g in _groups.Where(g => g.UnitNumber == group.UnitNumber))
        {
            sink.TagChanged(g.Change(name, TagQuality.CommError, time.GetUtcNow(), e.Exception.Message));
        }

        sink.UnitChanged(name, group.UnitNumber, UnitState.Demoted, e.Exception.Message);
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

    /// <summary>Whether a PLC on the link answers; while it does not, which group probes it and what the others wait for.</summary>
    private sealed class UnitHealth
    {
        public bool Down { get; set; }

        public bool Demoted { get; set; }

        /// <summary>The failure last reported for the unit (an outage and the demotion it causes carry the same one).</summary>
        public Exception? LastFailure { get; set; }

        public long Since { get; set; }

        public int Attempts { get; set; }

        public PollGroup? Prober { get; set; }

        public TimeSpan RetryDelay { get; set; }

        public TaskCompletionSource Answers { get; set; } = new();
    }
}
