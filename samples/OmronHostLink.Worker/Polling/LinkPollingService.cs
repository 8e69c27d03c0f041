using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using OmronHostLink.Transports;
using OmronHostLink.Worker.Configuration;
using OmronHostLink.Worker.Mqtt;

namespace OmronHostLink.Worker.Polling;

/// <summary>
/// Polls one link: one <see cref="HostLinkClient"/>, one loop, the link's groups taken in turn by
/// <see cref="PollScheduler{T}"/>. Every poll is caught: a PLC that stops answering is reported once, retried with
/// capped exponential backoff and reported again when it answers; nothing a PLC or a line does stops the host.
/// </summary>
public sealed class LinkPollingService : BackgroundService
{
    private readonly string _name;
    private readonly LinkOptions _options;
    private readonly ILoggerFactory _loggerFactory;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly Dictionary<int, UnitHealth> _units = new();
    private readonly ITagSink? _sink;
    private List<PollGroup> _groups = [];
    private long _origin;
    private long _polls;
    private long _failures;

    /// <summary>
    /// Creates the service for the link <paramref name="name"/>; nothing happens until it is started. A
    /// <paramref name="sink"/> receives every poll's outcome and the link's state.
    /// </summary>
    public LinkPollingService(string name, LinkOptions options, ILoggerFactory loggerFactory, TimeProvider? timeProvider = null, ITagSink? sink = null)
    {
        ArgumentNullException.ThrowIfNull(name);
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(loggerFactory);
        _name = name;
        _options = options;
        _loggerFactory = loggerFactory;
        _logger = loggerFactory.CreateLogger<LinkPollingService>();
        _time = timeProvider ?? TimeProvider.System;
        _sink = sink;
    }

    /// <summary>The link's name.</summary>
    public string Name => _name;

    private TimeSpan Now => _time.GetElapsedTime(_origin);

    /// <inheritdoc/>
    protected override async Task ExecuteAsync(CancellationToken stoppingToken)
    {
        // Let StartAsync return at once: the first connection attempt may block for the connect timeout.
        await Task.Yield();
        _origin = _time.GetTimestamp();
        HostLinkClient client;
        List<PollGroup> groups;
        try
        {
            client = CreateClient();
            groups = _options.Groups
                .Select(g => new PollGroup(g.Key, g.Value, client.Unit(g.Value.Unit), _options.WordOrder))
                .ToList();
        }
        catch (Exception e)
        {
            WorkerLog.LinkFailed(_logger, e, _name);
            _sink?.LinkChanged(_name, LinkState.Offline, e.Message);
            return;
        }

        await using (client.ConfigureAwait(false))
        {
            foreach (PollGroup g in groups)
            {
                if (!_units.ContainsKey(g.UnitNumber))
                {
                    _units.Add(g.UnitNumber, new UnitHealth());
                }
            }

            var scheduler = new PollScheduler<PollGroup>(groups.Select(g => (g, g.Interval)), Now);
            WorkerLog.LinkStarted(_logger, _name, groups.Count, client.Description);
            _groups = groups;
            _sink?.LinkOpened(_name, client);
            try
            {
                while (!stoppingToken.IsCancellationRequested)
                {
                    (int slot, TimeSpan at) = scheduler.Next(g => _units[g.UnitNumber].RetryAt);
                    TimeSpan wait = at - Now;
                    if (wait > TimeSpan.Zero)
                    {
                        await Task.Delay(wait, _time, stoppingToken).ConfigureAwait(false);
                    }

                    PollGroup group = scheduler[slot];
                    await PollAsync(group, stoppingToken).ConfigureAwait(false);
                    long skipped = scheduler.Completed(slot, Now);
                    if (skipped > 0 && !_units[group.UnitNumber].Down)
                    {
                        WorkerLog.TicksSkipped(_logger, _name, group.Name, skipped);
                    }
                }
            }
            catch (OperationCanceledException) when (stoppingToken.IsCancellationRequested)
            {
                // Stopping.
            }
        }

        _sink?.LinkChanged(_name, LinkState.Offline);
        WorkerLog.LinkStopped(_logger, _name, _polls, _failures);
    }

    private HostLinkClient CreateClient()
    {
        var options = new HostLinkClientOptions
        {
            TurnaroundAllowance = _options.TurnaroundAllowance,
            ReadRetries = _options.ReadRetries,
            CommandSet = _options.Protocol,
            WordOrder = _options.WordOrder,
            LoggerFactory = _loggerFactory,
        };
        if (_options.Serial is { } serial)
        {
            return HostLinkClient.ForSerialPort(serial, options);
        }

        if (_options.LineBaudRate is { } baud)
        {
            options.LineTiming = new LineTiming(baud, LineTiming.Default.BitsPerCharacter);
        }

        (string host, int port) = Transports.TcpTransport.ParseEndpoint(_options.Tcp!);
        return HostLinkClient.ForTcp(host, port, options, _options.ConnectTimeout);
    }

    private async Task PollAsync(PollGroup group, CancellationToken stoppingToken)
    {
        UnitHealth unit = _units[group.UnitNumber];
        _polls++;
        string values;
        try
        {
            values = await group.ReadAsync(stoppingToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (stoppingToken.IsCancellationRequested)
        {
            throw;
        }
        catch (HostLinkException e) when (e is HostLinkTimeoutException or HostLinkConnectionException or HostLinkFrameException)
        {
            _failures++;
            UnitFailed(group, unit, e);
            return;
        }
        catch (Exception e) when (e is HostLinkException or FormatException)
        {
            // The PLC answered (an end code, a word that is not BCD...): the unit is up, this group is not.
            _failures++;
            UnitAnswered(group, unit);
            if (group.Failure != e.Message)
            {
                group.Failure = e.Message;
                WorkerLog.GroupFailed(_logger, _name, group.Name, group.UnitNumber, group.AddressText, e.Message);
            }

            _sink?.TagChanged(group.Change(_name, TagQuality.Stale, _time.GetUtcNow(), e.Message));
            return;
        }
        catch (Exception e)
        {
            _failures++;
            if (group.Failure != e.Message)
            {
                group.Failure = e.Message;
                WorkerLog.GroupCrashed(_logger, e, _name, group.Name, group.UnitNumber, group.AddressText);
            }

            _sink?.TagChanged(group.Change(_name, TagQuality.Stale, _time.GetUtcNow(), e.Message));
            return;
        }

        UnitAnswered(group, unit);
        if (group.Failure is not null)
        {
            group.Failure = null;
            WorkerLog.GroupRecovered(_logger, _name, group.Name, group.UnitNumber, group.AddressText);
        }

        _sink?.TagChanged(group.Change(_name, TagQuality.Good, _time.GetUtcNow()));

        if (group.Mode == PollLogMode.EveryPoll || group.LastLogged != values)
        {
            group.LastLogged = values;
            WorkerLog.Values(_logger, _name, group.Name, group.UnitNumber, group.AddressText, values);
        }
    }

    private void UnitFailed(PollGroup group, UnitHealth unit, HostLinkException e)
    {
        string reason = e switch
        {
            HostLinkTimeoutException => "timeout",
            HostLinkConnectionException => "connection",
            _ => "damaged answers",
        };
        TimeSpan now = Now;
        if (!unit.Down)
        {
            unit.Down = true;
            unit.Since = now;
            unit.Attempts = 1;
            unit.Backoff = _options.Backoff.Initial;
            unit.RetryAt = now + unit.Backoff;
            WorkerLog.UnitDown(_logger, _name, group.UnitNumber, reason, e.Message, unit.Backoff.TotalSeconds, _options.Backoff.Max.TotalSeconds);
            if (_sink is not null)
            {
                // Every tag of the unit, not only the one that failed: none of them can be read now.
                foreach (PollGroup g in _groups.Where(g => g.UnitNumber == group.UnitNumber))
                {
                    _sink.TagChanged(g.Change(_name, TagQuality.CommError, _time.GetUtcNow(), e.Message));
                }

                _sink.LinkChanged(_name, LinkState.CommError, e.Message);
            }

            return;
        }

        unit.Attempts++;
        long doubled = Math.Min(unit.Backoff.Ticks * 2, _options.Backoff.Max.Ticks);
        unit.Backoff = TimeSpan.FromTicks(Math.Max(doubled, _options.Backoff.Initial.Ticks));
        unit.RetryAt = now + unit.Backoff;
        WorkerLog.UnitStillDown(_logger, _name, group.UnitNumber, reason, e.Message, unit.Backoff.TotalSeconds);
    }

    private void UnitAnswered(PollGroup group, UnitHealth unit)
    {
        if (!unit.Down)
        {
            return;
        }

        WorkerLog.UnitResumed(_logger, _name, group.UnitNumber, (Now - unit.Since).TotalSeconds, unit.Attempts);
        unit.Down = false;
        unit.Attempts = 0;
        unit.RetryAt = TimeSpan.Zero;
        if (!_units.Values.Any(u => u.Down))
        {
            _sink?.LinkChanged(_name, LinkState.Online);
        }
    }

    /// <summary>Whether a PLC on the link answers, and when to try it again if not.</summary>
    private sealed class UnitHealth
    {
        public bool Down { get; set; }

        public TimeSpan Since { get; set; }

        public int Attempts { get; set; }

        public TimeSpan Backoff { get; set; }

        /// <summary>While down: no group of this unit runs before this time. Zero while up.</summary>
        public TimeSpan RetryAt { get; set; }
    }
}
