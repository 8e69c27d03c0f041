using System.Collections.Concurrent;
using System.Diagnostics.Tracing;
using System.Globalization;
using Microsoft.Diagnostics.NETCore.Client;
using Microsoft.Diagnostics.Tracing;

namespace OmronHostLink.Gateway.Tests.Telemetry;

/// <summary>One value the runtime's metrics event source published for an instrument in another process.</summary>
/// <param name="Event">The event: CounterRateValuePublished, HistogramValuePublished, UpDownCounterRateValuePublished…</param>
/// <param name="Instrument">The instrument's name.</param>
/// <param name="Unit">The instrument's unit.</param>
/// <param name="Tags">The time series' tags, <c>key=value</c> joined by commas as the event carries them.</param>
/// <param name="Value">The value: a counter's rate and total, an up/down counter's value, a histogram's count, sum and quantiles.</param>
internal sealed record PublishedValue(string Event, string Instrument, string? Unit, string Tags, string Value);

/// <summary>
/// An EventPipe session on another .NET process with the <c>System.Diagnostics.Metrics</c> provider: the runtime
/// aggregates the named meters in that process and publishes every instrument's values each refresh interval. This is
/// what <c>dotnet-counters monitor --counters &lt;meter&gt;</c> does.
/// </summary>
internal sealed class MetricsEventPipeSession : IAsyncDisposable
{
    private const string Provider = "System.Diagnostics.Metrics";
    private const long TimeSeriesValues = 0x2;

    private readonly EventPipeSession _session;
    private readonly Task _processing;
    private readonly string _sessionId = Guid.NewGuid().ToString();
    private readonly ConcurrentQueue<PublishedValue> _values = new();
    private readonly ConcurrentQueue<string> _errors = new();

    private MetricsEventPipeSession(int processId, string meters, TimeSpan refreshInterval)
    {
        var provider = new EventPipeProvider(Provider, EventLevel.Informational, TimeSeriesValues, new Dictionary<string, string>
        {
            ["SessionId"] = _sessionId,
            ["Metrics"] = meters,
            ["RefreshInterval"] = refreshInterval.TotalSeconds.ToString(CultureInfo.InvariantCulture),
            ["MaxTimeSeries"] = "1000",
            ["MaxHistograms"] = "20",
        });
        _session = new DiagnosticsClient(processId).StartEventPipeSession([provider], requestRundown: false);
        _processing = Task.Run(() =>
        {
            using var source = new EventPipeEventSource(_session.EventStream);
            source.Dynamic.All += OnEvent;
            source.Process();
        });
    }

    /// <summary>Every value published so far, oldest first.</summary>
    public IReadOnlyList<PublishedValue> Values => _values.ToArray();

    /// <summary>Errors the event source reported (a second session, too many time series…).</summary>
    public IReadOnlyList<string> Errors => _errors.ToArray();

    /// <summary>Starts a session on <paramref name="processId"/> for the meters named (comma-separated).</summary>
    public static MetricsEventPipeSession Start(int processId, string meters, TimeSpan refreshInterval) => new(processId, meters, refreshInterval);

    /// <summary>Waits until a value satisfies <paramref name="predicate"/>; false after <paramref name="timeout"/>.</summary>
    public async Task<bool> WaitForAsync(Func<IReadOnlyList<PublishedValue>, bool> predicate, TimeSpan timeout)
    {
        try
        {
            await Eventually.UntilAsync(() => predicate(Values) || _processing.IsCompleted, "the session receives the values", patience: timeout);
        }
        catch (TimeoutException)
        {
        }

        return predicate(Values);
    }

    public async ValueTask DisposeAsync()
    {
        try
        {
            await _session.StopAsync(CancellationToken.None);
        }
        catch (ServerNotAvailableException)
        {
            // The process is gone; its stream has ended.
        }

        await _processing.WaitAsync(TimeSpan.FromSeconds(10));
        _session.Dispose();
    }

    private void OnEvent(TraceEvent e)
    {
        if (e.ProviderName != Provider)
        {
            return;
        }

        if (e.EventName is "Error" or "MultipleSessionsNotSupportedError" or "MultipleSessionsConfiguredIncorrectlyError"
            or "TimeSeriesLimitReached" or "HistogramLimitReached" or "ObservableInstrumentCallbackError")
        {
            _errors.Enqueue($"{e.EventName}: {string.Join(", ", e.PayloadNames.Select(n => $"{n}={e.PayloadByName(n)}"))}");
            return;
        }

        if ((string?)e.PayloadByName("sessionId") != _sessionId)
        {
            return;
        }

        string? value = e.EventName switch
        {
            "CounterRateValuePublished" or "UpDownCounterRateValuePublished" => $"rate={e.PayloadByName("rate")} value={Payload(e, "value")}",
            "HistogramValuePublished" => $"count={Payload(e, "count")} sum={Payload(e, "sum")} quantiles={e.PayloadByName("quantiles")}",
            "GaugeValuePublished" => $"value={e.PayloadByName("lastValue")}",
            _ => null,
        };
        if (value is not null)
        {
            _values.Enqueue(new PublishedValue(e.EventName!, (string)e.PayloadByName("instrumentName"), (string?)e.PayloadByName("unit"), (string)e.PayloadByName("tags"), value));
        }
    }

    private static object? Payload(TraceEvent e, string name)
        => Array.IndexOf(e.PayloadNames, name) >= 0 ? e.PayloadByName(name) : "(not in this runtime's event)";
}
