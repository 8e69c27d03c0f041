using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Statistics;
using OmronHostLink.Transports;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// The Lines view: each enabled link with its endpoint, speed and format, state, transactions per second and figures
/// (<see cref="LinkStatistics"/>), each of its units with its state since when, last error and figures, and its scan
/// classes (the groups of a unit at one interval).
/// </summary>
/// <param name="gateway">The validated <c>HostLink</c> section.</param>
/// <param name="statistics">The figures per link and unit.</param>
/// <param name="timeline">States over time and last errors.</param>
/// <param name="rates">Transactions per second.</param>
/// <param name="time">The clock.</param>
internal sealed class LinesView(IOptions<GatewayOptions> gateway, LinkStatistics statistics, UnitTimeline timeline, TransactionRates rates, TimeProvider time)
{
    /// <summary>The view now.</summary>
    public LinesDocument Snapshot()
    {
        IReadOnlyList<UnitStatistics> units = statistics.Units();
        var links = new List<LinkView>();
        foreach ((string name, LinkOptions options) in gateway.Value.Links.Where(l => l.Value.Enabled).OrderBy(l => l.Key, StringComparer.Ordinal))
        {
            UnitStatistics totals = statistics.Link(name);
            var link = timeline.Link(name);
            (string endpoint, string line) = Where(options);
            links.Add(new LinkView
            {
                Name = name,
                State = link?.State.Name() ?? LinkState.Offline.Name(),
                Since = link?.Since,
                Detail = link?.Detail,
                Endpoint = endpoint,
                Line = line,
                CommandSet = options.CommandSet.ToString(),
                TransactionsPerSecond = rates.Sample(name, totals.Transactions),
                Totals = totals,
                Units = units.Where(u => u.Link == name).Select(u => Unit(name, u)).ToList(),
                ScanClasses = ScanClasses(options, totals.ScanClasses),
            });
        }

        return new LinesDocument { Now = time.GetUtcNow(), Links = links };
    }

    private UnitView Unit(string link, UnitStatistics figures)
    {
        int unit = figures.Unit!.Value;
        var (state, since, lastError, lastErrorTime, events) = timeline.Unit(link, unit);
        return new UnitView
        {
            Unit = unit,
            State = state.Name(),
            Since = since,
            LastError = lastError,
            LastErrorTime = lastErrorTime,
            Figures = figures,
            Events = events,
        };
    }

    /// <summary>Where the link goes and its line's speed and format, from its settings.</summary>
    private static (string Endpoint, string Line) Where(LinkOptions options)
    {
        HostLinkClientSettings client = options.Client;
        SerialLineSettings line = client.Serial.ToLineSettings();
        if (!string.IsNullOrEmpty(client.Tcp.Host))
        {
            return ($"{client.Tcp.Host}:{client.Tcp.Port}", $"{line.BaudRate} bps on the serial side of the device server");
        }

        // The settings' own short form, "/dev/ttyUSB0 9600 7E2", without the port and with the unit of the speed.
        string format = line.ToString()[(line.PortName.Length + 1)..];
        int speedEnd = format.IndexOf(' ', StringComparison.Ordinal);
        return (line.PortName, speedEnd < 0 ? format : format.Insert(speedEnd, " bps"));
    }

    /// <summary>The groups of each unit by interval, shortest first, each with its plan and cycle times from the statistics.</summary>
    private static List<ScanClassView> ScanClasses(LinkOptions options, IReadOnlyList<ScanClassStatistics> measured)
        => options.Groups
            .GroupBy(g => (g.Value.Unit, g.Value.Interval))
            .OrderBy(c => c.Key.Unit).ThenBy(c => c.Key.Interval)
            .Select(c =>
            {
                ScanClassStatistics? figures = measured.FirstOrDefault(m => m.Unit == c.Key.Unit && m.IntervalMs == c.Key.Interval.TotalMilliseconds);
                return new ScanClassView
                {
                    Unit = c.Key.Unit,
                    IntervalMs = c.Key.Interval.TotalMilliseconds,
                    Groups = c.Select(g => g.Key).Order(StringComparer.Ordinal).ToList(),
                    MeasuredCycleMs = figures?.LastCycleMs,
                    AverageCycleMs = figures?.AverageCycleMs,
                    EstimatedCycleMs = figures is { Reads: > 0 } ? figures.EstimatedCycleMs : null,
                    Reads = figures is { Reads: > 0 } ? figures.Reads : null,
                    Overruns = figures?.Overruns ?? 0,
                };
            })
            .ToList();
}
