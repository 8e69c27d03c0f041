using System.Globalization;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Planning;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// The gateway's plan without a PLC (<c>OmronHostLink.Gateway --plan</c>): for each enabled link, its scan classes —
/// the groups and tag-file rows of one unit at one interval — and the reads each makes a cycle, with the time they
/// take at the line's speed and the cycle the class can expect on the line it shares with the link's others. The plans are the watches' own (their first, made before any exchange), so they are
/// the ones the gateway starts with.
/// </summary>
internal static class ScanPlanReport
{
    /// <summary>Writes the plan of every enabled link of <paramref name="options"/> to <paramref name="output"/>.</summary>
    public static async Task WriteAsync(GatewayOptions options, TextWriter output)
    {
        foreach ((string name, LinkOptions link) in options.Links.Where(l => l.Value.Enabled).OrderBy(l => l.Key, StringComparer.OrdinalIgnoreCase))
        {
            // No exchange is made: a watch reports its first plan before its first read.
            await using HostLinkClient client = HostLinkClient.ForStream(Stream.Null, link.Client.ToClientOptions());
            List<PollScan> scans = PollScan.Classes(link.Groups.Select(g => new PollGroup(g.Key, g.Value, client.Unit(g.Value.Unit), link.WordOrder)), client);
            List<IAsyncEnumerator<WatchEvent>> watches = scans
                .Select(s => s.Unit.WatchAsync(s.Tags, new WatchOptions { Interval = s.Interval, ReportPlans = true }).GetAsyncEnumerator())
                .ToList();
            try
            {
                for (int i = 0; i < scans.Count; i++)
                {
                    await watches[i].MoveNextAsync().ConfigureAwait(false);
                    scans[i].Plan = watches[i].Current.Plan;
                }
            }
            finally
            {
                foreach (IAsyncEnumerator<WatchEvent> watch in watches)
                {
                    await watch.DisposeAsync().ConfigureAwait(false);
                }
            }

            TimeSpan gap = link.Client.SendInterval ?? TimeSpan.Zero;
            ReadPlan?[] pending = scans.Select(s => PendingCompound(s, link)).ToArray();
            LineSchedule.Watch[] now = scans.Select(s => s.OnLine(s.Plan!, gap)).ToArray();
            LineSchedule.Watch[] then = scans.Select((s, i) => s.OnLine(pending[i] ?? s.Plan!, gap)).ToArray();
            TimeSpan[] cycles = LineSchedule.ExpectedCycles(now);
            TimeSpan[] cyclesThen = pending.Any(p => p is not null) ? LineSchedule.ExpectedCycles(then) : cycles;
            double load = then.Sum(w => w.LineTime.TotalSeconds / w.Interval.TotalSeconds);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"link {name}: {link.Groups.Count} tag(s) in {scans.Count} scan class(es) on {client.LineTiming.BaudRate} bps, {load:P0} of the line's time"));
            for (int i = 0; i < scans.Count; i++)
            {
                PollScan scan = scans[i];
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  unit {scan.UnitNumber} every {PollScan.Durations(scan.Interval)}: {scan.Groups.Count} tag(s) in {scan.Plan}{Fit(cycles[i], now[i].LineTime, scan.Interval)}"));
                foreach (PlannedRead read in scan.Plan!.Reads)
                {
                    output.WriteLine($"    {read}");
                }

                if (pending[i] is { } qq)
                {
                    output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"    once the unit names its model (MM), and where that model has QQ: {qq}{Fit(cyclesThen[i], then[i].LineTime, scan.Interval)}"));
                }
            }
        }
    }

    /// <summary>
    /// The plan a scan class will read with once its unit names its model with MM, when QQ waits for that (the link's
    /// UseCompoundRead is Auto, and no model is configured) and would change the plan; null otherwise.
    /// </summary>
    public static ReadPlan? PendingCompound(PollScan scan, LinkOptions link)
    {
        if (scan.Plan is not { } plan || scan.Unit.CommandSet != HostLinkCommandSet.CMode
            || (link.Client.UseCompoundRead ?? CompoundReadMode.Auto) != CompoundReadMode.Auto
            || plan.Reads.Any(r => r.Kind == PlannedReadKind.CModeCompound)
            || (link.Client.Model is { } model && !model.Equals("auto", StringComparison.OrdinalIgnoreCase)))
        {
            return null;
        }

        ReadPlan qq = new ReadPlanner(scan.Unit.CommandSet, scan.Unit.LineTiming) { UseCompoundRead = CompoundReadMode.On }.Plan(scan.Tags, scan.UnitNumber);
        return qq.Reads.Any(r => r.Kind == PlannedReadKind.CModeCompound) ? qq : null;
    }

    /// <summary>The expected cycle on the shared line, the class's own time on it, and how it fits the interval.</summary>
    private static string Fit(TimeSpan cycle, TimeSpan lineTime, TimeSpan interval)
        => cycle > interval
            ? string.Create(CultureInfo.InvariantCulture, $" — {PollScan.Durations(cycle)} a cycle on the line ({PollScan.Durations(lineTime)} of its own), more than its interval: read every {PollScan.Durations(cycle)} at best")
            : string.Create(CultureInfo.InvariantCulture, $" — {PollScan.Durations(cycle)} a cycle on the line ({PollScan.Durations(lineTime)} of its own), {cycle / interval:P0} of its interval");
}
