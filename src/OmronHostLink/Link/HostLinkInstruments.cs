using System.Diagnostics;
using System.Diagnostics.Metrics;
using System.Runtime.CompilerServices;

namespace OmronHostLink.Link;

/// <summary>
/// The instruments of one <see cref="HostLinkTelemetry.MeterName"/> meter, named after OpenTelemetry's conventions.
/// One set per meter: the shared static meter's when no <see cref="IMeterFactory"/> is given, else one per factory
/// (the factory owns its meter and disposes it; a set is kept only as long as its factory lives).
/// </summary>
internal sealed class HostLinkInstruments
{
    public const string OperationDurationName = "hostlink.client.operation.duration";
    public const string RetriesName = "hostlink.client.retries";
    public const string ConnectionCountName = "hostlink.client.connection.count";
    public const string ExchangeDurationName = "hostlink.client.exchange.duration";

    /// <summary>
    /// Bucket boundaries in seconds for serial timings: a one-word read crosses the line in ~3 ms at 115200 and ~35 ms
    /// at 9600, a 1000-word read in ~5 s at 9600, and a timeout costs the turnaround allowance (300 ms by default) per
    /// attempt.
    /// </summary>
    internal static readonly double[] DurationBuckets = [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 30];

    private static readonly ConditionalWeakTable<IMeterFactory, HostLinkInstruments> ByFactory = new();

    // Small numbers (unit numbers, frame and retry counts) boxed once: a tag value is an object, and a measurement
    // should not allocate one.
    private static readonly object[] SmallNumbers = Enumerable.Range(0, 64).Select(u => (object)u).ToArray();

    private static HostLinkInstruments? s_shared;

    // Open transports by link name, observed when a listener collects: a late listener (dotnet-counters attached to a
    // running process) sees the links already open, which a counter of opens and closes could not tell it.
    private readonly Dictionary<string, long> _open = new(StringComparer.Ordinal);

    private HostLinkInstruments(Meter meter)
    {
        OperationDuration = meter.CreateHistogram(
            OperationDurationName,
            "s",
            "Duration of Host Link commands, from the call to the answer or the final error, waiting for the line, resynchronisation and retries included.",
            tags: null,
            advice: new InstrumentAdvice<double> { HistogramBucketBoundaries = DurationBuckets });
        ExchangeDuration = meter.CreateHistogram(
            ExchangeDurationName,
            "s",
            "Duration of the answered attempt of Host Link commands, from its first frame sent to its answer's last frame: the PLC's response time on the line, without waiting for the line, resynchronisation or failed attempts.",
            tags: null,
            advice: new InstrumentAdvice<double> { HistogramBucketBoundaries = DurationBuckets });
        Retries = meter.CreateCounter<long>(RetriesName, "{retry}", "Attempts repeated after a timeout or a damaged frame, by the error of the attempt that failed.");
        ConnectionCount = meter.CreateObservableUpDownCounter(ConnectionCountName, ObserveOpen, "{connection}", "Links whose transport (serial port, TCP connection, stream) is open.");
    }

    /// <summary>The set on the library's one static meter, made on first use.</summary>
    public static HostLinkInstruments Shared
    {
        get
        {
            HostLinkInstruments? shared = Volatile.Read(ref s_shared);
            if (shared is null)
            {
                var made = new HostLinkInstruments(new Meter(HostLinkTelemetry.MeterName, Version));
                shared = Interlocked.CompareExchange(ref s_shared, made, null) ?? made;
            }

            return shared;
        }
    }

    /// <summary>The library's version, as the meter's and activity source's (the informational version without its commit).</summary>
    public static string? Version { get; } = ReadVersion();

    public Histogram<double> OperationDuration { get; }

    public Histogram<double> ExchangeDuration { get; }

    public Counter<long> Retries { get; }

    public ObservableUpDownCounter<long> ConnectionCount { get; }

    /// <summary>The set for <paramref name="factory"/>'s meter, or <see cref="Shared"/> without a factory.</summary>
    public static HostLinkInstruments For(IMeterFactory? factory)
        => factory is null
            ? Shared
            : ByFactory.GetValue(factory, f => new HostLinkInstruments(f.Create(new MeterOptions(HostLinkTelemetry.MeterName) { Version = Version })));

    /// <summary>The number as a tag value: 0-63 (every unit number, most frame and retry counts) are boxed once.</summary>
    public static object Boxed(int number) => (uint)number < (uint)SmallNumbers.Length ? SmallNumbers[number] : number;

    /// <summary>Records one command's duration; <paramref name="failure"/> is null when it succeeded.</summary>
    public void Operation(string link, int unit, string command, Exception? failure, TimeSpan elapsed)
    {
        if (!OperationDuration.Enabled)
        {
            return;
        }

        TagList tags = Tags(link, unit, command);
        if (failure is not null)
        {
            tags.Add(TelemetryTags.ErrorType, ErrorTypes.Of(failure));
        }

        OperationDuration.Record(elapsed.TotalSeconds, tags);
    }

    /// <summary>Records the response time of a command's answered attempt.</summary>
    public void Exchange(string link, int unit, string command, TimeSpan elapsed)
    {
        if (ExchangeDuration.Enabled)
        {
            ExchangeDuration.Record(elapsed.TotalSeconds, Tags(link, unit, command));
        }
    }

    /// <summary>Counts one repeated attempt, by what ended the one before.</summary>
    public void Retry(string link, int unit, string command, Exception failure)
    {
        if (!Retries.Enabled)
        {
            return;
        }

        TagList tags = Tags(link, unit, command);
        tags.Add(TelemetryTags.ErrorType, ErrorTypes.Of(failure));
        Retries.Add(1, tags);
    }

    /// <summary>Counts a link's transport as opened (+1) or closed (-1).</summary>
    public void Connection(string link, int change)
    {
        lock (_open)
        {
            _open.TryGetValue(link, out long open);
            open += change;
            if (open == 0)
            {
                // Gone from the next collection: names of links that were closed do not pile up.
                _open.Remove(link);
            }
            else
            {
                _open[link] = open;
            }
        }
    }

    private IEnumerable<Measurement<long>> ObserveOpen()
    {
        lock (_open)
        {
            return _open.Select(o => new Measurement<long>(o.Value, new KeyValuePair<string, object?>(TelemetryTags.LinkName, o.Key))).ToArray();
        }
    }

    private static TagList Tags(string link, int unit, string command) => new()
    {
        { TelemetryTags.LinkName, link },
        { TelemetryTags.Unit, Boxed(unit) },
        { TelemetryTags.Command, command },
    };

    private static string? ReadVersion()
    {
        string? version = typeof(HostLinkInstruments).Assembly
            .GetCustomAttributes(typeof(System.Reflection.AssemblyInformationalVersionAttribute), false)
            .OfType<System.Reflection.AssemblyInformationalVersionAttribute>()
            .FirstOrDefault()?.InformationalVersion;
        int plus = version?.IndexOf('+') ?? -1;
        return plus >= 0 ? version!.Substring(0, plus) : version;
    }
}
