using System.Diagnostics;
using System.Diagnostics.Metrics;

namespace OmronHostLink.Link;

/// <summary>
/// The library's meter, <c>OmronHostLink</c>: transactions, their duration, retries and errors by kind and end code.
/// Watch it with <c>dotnet-counters monitor --counters OmronHostLink -n &lt;process&gt;</c>.
/// </summary>
public static class HostLinkMetrics
{
    /// <summary>The meter's name.</summary>
    public const string MeterName = "OmronHostLink";

    private static readonly Meter Meter = new(MeterName, "1.0");

    private static readonly Counter<long> Transactions = Meter.CreateCounter<long>("hostlink.transactions", "{transaction}", "Completed Host Link transactions (success or PLC error answer).");

    private static readonly Histogram<double> Duration = Meter.CreateHistogram<double>("hostlink.transaction.duration", "ms", "Time from the first byte sent to the last byte received.");

    private static readonly Counter<long> Errors = Meter.CreateCounter<long>("hostlink.errors", "{error}", "Failed attempts by kind (timeout, frame, end_code, connection, cancelled) and end code.");

    private static readonly Counter<long> Retries = Meter.CreateCounter<long>("hostlink.retries", "{retry}", "Attempts repeated after a timeout or damaged frame.");

    internal static void Completed(string header, double milliseconds)
    {
        var tags = new TagList { { "header", header } };
        Transactions.Add(1, tags);
        Duration.Record(milliseconds, tags);
    }

    internal static void Error(string header, string kind, string? endCode)
    {
        var tags = new TagList { { "header", header }, { "kind", kind } };
        if (endCode is not null)
        {
            tags.Add("end_code", endCode);
        }

        Errors.Add(1, tags);
    }

    internal static void Retry(string header) => Retries.Add(1, new TagList { { "header", header } });
}
