using System.Diagnostics.Metrics;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Statistics;

/// <summary>
/// The figures a technician reads per link and PLC unit, since the gateway started: transactions, failures by kind,
/// retries, last and average response time, demoted or not. They are counted from the library's own instruments
/// (<c>hostlink.client.operation.duration</c>, <c>hostlink.client.retries</c>,
/// <c>hostlink.client.exchange.duration</c>) through a <see cref="MeterListener"/> on the container's meter — the
/// measurements an OpenTelemetry exporter sends, not a second set of counters — and the unit states come from the
/// polling (this is an output). The demotions are instruments of the gateway's meter:
/// <c>hostlink.gateway.unit.demoted</c> and <c>hostlink.gateway.unit.demotions</c>.
/// </summary>
internal sealed class LinkStatistics : ITagOutput, IScanOutput, IDisposable
{
    /// <summary>Gauge: 1 for a demoted unit, 0 for the others (attributes <c>hostlink.link.name</c>, <c>hostlink.unit</c>).</summary>
    public const string DemotedName = "hostlink.gateway.unit.demoted";

    /// <summary>Counter: demotions of a unit.</summary>
    public const string DemotionsName = "hostlink.gateway.unit.demotions";

    /// <summary>
    /// Histogram: each scan class's cycle time, from the start of a cycle to its last answer, in seconds (attributes
    /// <c>hostlink.link.name</c>, <c>hostlink.unit</c>, <c>hostlink.scan.interval</c> in seconds).
    /// </summary>
    public const string CycleDurationName = "hostlink.gateway.scan.cycle.duration";

    /// <summary>Gauge: each scan class's planned cycle time (the least its reads take on the line), in seconds; same attributes.</summary>
    public const string CycleEstimateName = "hostlink.gateway.scan.cycle.estimated";

    private const string IntervalTag = "hostlink.scan.interval";

    private const string OperationDuration = "hostlink.client.operation.duration";
    private const string ExchangeDuration = "hostlink.client.exchange.duration";
    private const string Retries = "hostlink.client.retries";
    private const string LinkNameTag = "hostlink.link.name";
    private const string UnitTag = "hostlink.unit";
    private const string ErrorTypeTag = "error.type";

    private readonly object _gate = new();
    private readonly SortedDictionary<(string Link, int Unit), Tally> _units = new();
    private readonly SortedDictionary<(string Link, int Unit, TimeSpan Interval), ScanTally> _scans = new();
    private readonly Histogram<double> _cycles;
    private readonly Dictionary<string, LinkState> _links = new(StringComparer.Ordinal);
    private readonly MeterListener _listener;
    private readonly TimeProvider _time;
    private readonly Counter<long> _demotions;
    private readonly DateTimeOffset _since;

    /// <summary>Starts counting: every configured unit of the enabled links is listed from the start.</summary>
    /// <param name="options">The validated <c>HostLink</c> section.</param>
    /// <param name="meterFactory">The container's meter factory: the links' clients measure through it.</param>
    /// <param name="time">The clock of the timestamps.</param>
    public LinkStatistics(IOptions<GatewayOptions> options, IMeterFactory meterFactory, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(meterFactory);
        _time = time;
        _since = time.GetUtcNow();
        foreach ((string link, LinkOptions linkOptions) in options.Value.Links)
        {
            if (linkOptions is { Enabled: true })
            {
                foreach (PollGroupOptions group in linkOptions.Groups.Values)
                {
                    _units.TryAdd((link, group.Unit), new Tally());
                }
            }
        }

        Meter meter = meterFactory.Create(GatewayNames.Meter);
        meter.CreateObservableGauge(DemotedName, ObserveDemoted, "{unit}", "1 while a PLC unit is demoted (not polled, probed once a demotion period), else 0.");
        _demotions = meter.CreateCounter<long>(DemotionsName, "{demotion}", "PLC units demoted after staying silent Demotion:After polls in a row.");
        _cycles = meter.CreateHistogram<double>(CycleDurationName, "s", "Scan class cycle time: every tag of one unit at one interval read, from the cycle's start to its last answer.");
        meter.CreateObservableGauge(CycleEstimateName, ObserveEstimates, "s", "Scan class planned cycle time: the least its reads take on the line.");

        _listener = new MeterListener
        {
            InstrumentPublished = (instrument, listener) =>
            {
                // Only this container's clients: a test process may run several gateways.
                if (instrument.Meter.Name == HostLinkTelemetry.MeterName && ReferenceEquals(instrument.Meter.Scope, meterFactory)
                    && instrument.Name is OperationDuration or ExchangeDuration or Retries)
                {
                    listener.EnableMeasurementEvents(instrument);
                }
            },
        };
        _listener.SetMeasurementEventCallback<double>(OnMeasurement);
        _listener.SetMeasurementEventCallback<long>((instrument, value, tags, _) => OnMeasurement(instrument, value, tags, null));
        _listener.Start();
    }

    /// <summary>A unit's state changed (link, unit): its figures are worth publishing now rather than at the next interval.</summary>
    public event Action<string, int>? UnitStateChanged;

    /// <summary>The figures of every unit, by link and unit number.</summary>
    public IReadOnlyList<UnitStatistics> Units()
    {
        DateTimeOffset now = _time.GetUtcNow();
        lock (_gate)
        {
            return _units.Select(u => u.Value.ToStatistics(u.Key.Link, u.Key.Unit, u.Value.State.Name(), _since, now, ScanClasses(u.Key.Link, u.Key.Unit))).ToList();
        }
    }

    /// <summary>The figures of one unit; null for a unit the gateway does not poll.</summary>
    public UnitStatistics? Unit(string link, int unit)
    {
        lock (_gate)
        {
            return _units.TryGetValue((link, unit), out Tally? tally)
                ? tally.ToStatistics(link, unit, tally.State.Name(), _since, _time.GetUtcNow(), ScanClasses(link, unit))
                : null;
        }
    }

    /// <summary>The totals of a link's units.</summary>
    public UnitStatistics Link(string link)
    {
        lock (_gate)
        {
            var total = new Tally();
            foreach (Tally unit in _units.Where(u => u.Key.Link == link).Select(u => u.Value))
            {
                total.Add(unit);
            }

            string state = _links.TryGetValue(link, out LinkState linkState) ? linkState.Name() : LinkState.Offline.Name();
            return total.ToStatistics(link, null, state, _since, _time.GetUtcNow(), ScanClasses(link, null));
        }
    }

    /// <summary>The links with statistics.</summary>
    public IReadOnlyList<string> LinkNames()
    {
        lock (_gate)
        {
            return _units.Keys.Select(k => k.Link).Distinct().ToList();
        }
    }

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client) => LinkChanged(link, LinkState.Online);

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        lock (_gate)
        {
            _links[link] = state;
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
    }

    /// <inheritdoc/>
    public void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
        lock (_gate)
        {
            Tally tally = TallyOf(link, unit);
            if (tally.State == state)
            {
                return;
            }

            tally.State = state;
            if (state == UnitState.Demoted)
            {
                tally.Demotions++;
                _demotions.Add(1, new KeyValuePair<string, object?>(LinkNameTag, link), new KeyValuePair<string, object?>(UnitTag, unit));
            }
        }

        UnitStateChanged?.Invoke(link, unit);
    }

    /// <inheritdoc/>
    public void ScanPlanned(ScanPlan plan)
    {
        ArgumentNullException.ThrowIfNull(plan);
        lock (_gate)
        {
            ScanOf(plan.Link, plan.Unit, plan.Interval).Plan = plan;
        }
    }

    /// <inheritdoc/>
    public void ScanCycled(ScanCycle cycle)
    {
        ArgumentNullException.ThrowIfNull(cycle);
        lock (_gate)
        {
            ScanTally scan = ScanOf(cycle.Link, cycle.Unit, cycle.Interval);
            scan.Cycles++;
            scan.Total += cycle.Duration;
            scan.Last = cycle.Duration;
            scan.Overruns += cycle.Overran ? 1 : 0;
        }

        _cycles.Record(
            cycle.Duration.TotalSeconds,
            new KeyValuePair<string, object?>(LinkNameTag, cycle.Link),
            new KeyValuePair<string, object?>(UnitTag, cycle.Unit),
            new KeyValuePair<string, object?>(IntervalTag, cycle.Interval.TotalSeconds));
    }

    /// <inheritdoc/>
    public void Dispose() => _listener.Dispose();

    private ScanTally ScanOf(string link, int unit, TimeSpan interval)
    {
        if (!_scans.TryGetValue((link, unit, interval), out ScanTally? scan))
        {
            _scans.Add((link, unit, interval), scan = new ScanTally());
        }

        return scan;
    }

    /// <summary>The scan classes of a unit (or, <paramref name="unit"/> null, of every unit of the link), under the gate.</summary>
    private List<ScanClassStatistics> ScanClasses(string link, int? unit)
        => _scans
            .Where(s => s.Key.Link == link && (unit is null || s.Key.Unit == unit))
            .Select(s => s.Value.ToStatistics(s.Key.Unit, s.Key.Interval))
            .ToList();

    private IEnumerable<Measurement<double>> ObserveEstimates()
    {
        lock (_gate)
        {
            return _scans.Where(s => s.Value.Plan is not null).Select(s => new Measurement<double>(
                s.Value.Plan!.EstimatedCycle.TotalSeconds,
                new KeyValuePair<string, object?>(LinkNameTag, s.Key.Link),
                new KeyValuePair<string, object?>(UnitTag, s.Key.Unit),
                new KeyValuePair<string, object?>(IntervalTag, s.Key.Interval.TotalSeconds))).ToArray();
        }
    }


    private Tally TallyOf(string link, int unit)
    {
        if (!_units.TryGetValue((link, unit), out Tally? tally))
        {
            tally = new Tally();
            _units.Add((link, unit), tally);
        }

        return tally;
    }

    private void OnMeasurement(Instrument instrument, double value, ReadOnlySpan<KeyValuePair<string, object?>> tags, object? state)
    {
        string? link = null;
        int unit = -1;
        string? error = null;
        foreach (KeyValuePair<string, object?> tag in tags)
        {
            switch (tag.Key)
            {
                case LinkNameTag:
                    link = tag.Value as string;
                    break;
                case UnitTag:
                    unit = tag.Value is int u ? u : -1;
                    break;
                case ErrorTypeTag:
                    error = tag.Value as string;
                    break;
            }
        }

        if (link is null || unit < 0)
        {
            return;
        }

        lock (_gate)
        {
            Tally tally = TallyOf(link, unit);
            switch (instrument.Name)
            {
                case OperationDuration:
                    tally.Transactions++;
                    if (error is not null)
                    {
                        tally.FailuresByKind[error] = tally.FailuresByKind.GetValueOrDefault(error) + 1;
                    }

                    break;
                case ExchangeDuration:
                    tally.Answered(value, _time.GetTimestamp());
                    break;
                default:
                    tally.Retries += (long)value;
                    break;
            }
        }
    }

    private IEnumerable<Measurement<int>> ObserveDemoted()
    {
        lock (_gate)
        {
            return _units.Select(u => new Measurement<int>(
                u.Value.State == UnitState.Demoted ? 1 : 0,
                new KeyValuePair<string, object?>(LinkNameTag, u.Key.Link),
                new KeyValuePair<string, object?>(UnitTag, u.Key.Unit))).ToArray();
        }
    }

    /// <summary>The running figures of a unit (or the sum of several).</summary>
    private sealed class Tally
    {
        public UnitState State { get; set; }

        public long Demotions { get; set; }

        public long Transactions { get; set; }

        public SortedDictionary<string, long> FailuresByKind { get; } = new(StringComparer.Ordinal);

        public long Retries { get; set; }

        public long Responses { get; private set; }

        public double ResponseSeconds { get; private set; }

        public double? LastResponseSeconds { get; private set; }

        public long LastResponseAt { get; private set; }

        public bool AnyDemoted { get; private set; }

        public void Answered(double seconds, long at)
        {
            Responses++;
            ResponseSeconds += seconds;
            LastResponseSeconds = seconds;
            LastResponseAt = at;
        }

        public void Add(Tally unit)
        {
            AnyDemoted |= unit.State == UnitState.Demoted;
            Demotions += unit.Demotions;
            Transactions += unit.Transactions;
            Retries += unit.Retries;
            foreach ((string kind, long count) in unit.FailuresByKind)
            {
                FailuresByKind[kind] = FailuresByKind.GetValueOrDefault(kind) + count;
            }

            Responses += unit.Responses;
            ResponseSeconds += unit.ResponseSeconds;
            if (unit.LastResponseSeconds is not null && unit.LastResponseAt >= LastResponseAt)
            {
                LastResponseSeconds = unit.LastResponseSeconds;
                LastResponseAt = unit.LastResponseAt;
            }
        }

        public UnitStatistics ToStatistics(string link, int? unit, string state, DateTimeOffset since, DateTimeOffset now, IReadOnlyList<ScanClassStatistics> scanClasses) => new()
        {
            ScanClasses = scanClasses,
            Link = link,
            Unit = unit,
            State = state,
            Demoted = unit is null ? AnyDemoted : State == UnitState.Demoted,
            Demotions = Demotions,
            Transactions = Transactions,
            Failures = FailuresByKind.Values.Sum(),
            FailuresByKind = new SortedDictionary<string, long>(FailuresByKind, StringComparer.Ordinal),
            Retries = Retries,
            LastResponseMs = LastResponseSeconds * 1000,
            AverageResponseMs = Responses == 0 ? null : ResponseSeconds / Responses * 1000,
            Since = since,
            Time = now,
        };
    }

    /// <summary>The running figures of a scan class.</summary>
    private sealed class ScanTally
    {
        public ScanPlan? Plan { get; set; }

        public long Cycles { get; set; }

        public TimeSpan Total { get; set; }

        public TimeSpan? Last { get; set; }

        public long Overruns { get; set; }

        public ScanClassStatistics ToStatistics(int unit, TimeSpan interval) => new()
        {
            Unit = unit,
            IntervalMs = interval.TotalMilliseconds,
            Tags = Plan?.Tags ?? 0,
            Reads = Plan?.Reads ?? 0,
            Characters = Plan?.Characters ?? 0,
            LineTimeMs = Plan?.LineTime.TotalMilliseconds ?? 0,
            EstimatedCycleMs = Plan?.EstimatedCycle.TotalMilliseconds ?? 0,
            Cycles = Cycles,
            LastCycleMs = Last?.TotalMilliseconds,
            AverageCycleMs = Cycles == 0 ? null : Total.TotalMilliseconds / Cycles,
            Overruns = Overruns,
        };
    }
}
