using System.Diagnostics;
using System.Diagnostics.Metrics;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// <see cref="ReadPathBenchmarks"/> with someone listening, as an OpenTelemetry SDK does: every <c>OmronHostLink</c>
/// instrument enabled (measurements taken and dropped) and every span sampled with all its data. The difference to the
/// unobserved read path is what telemetry costs once it is switched on.
/// </summary>
public class ObservedReadPathBenchmarks : ReadPathBenchmarks
{
    private MeterListener? _meters;
    private ActivityListener? _activities;

    protected override void StartListening()
    {
        _meters = new MeterListener
        {
            InstrumentPublished = (instrument, listener) =>
            {
                if (instrument.Meter.Name == HostLinkTelemetry.MeterName)
                {
                    listener.EnableMeasurementEvents(instrument);
                }
            },
        };
        _meters.SetMeasurementEventCallback<double>(static (_, _, _, _) => { });
        _meters.SetMeasurementEventCallback<long>(static (_, _, _, _) => { });
        _meters.Start();
        _activities = new ActivityListener
        {
            ShouldListenTo = source => source.Name == HostLinkTelemetry.ActivitySourceName,
            Sample = static (ref ActivityCreationOptions<ActivityContext> _) => ActivitySamplingResult.AllDataAndRecorded,
        };
        ActivitySource.AddActivityListener(_activities);
    }

    protected override void StopListening()
    {
        _activities?.Dispose();
        _meters?.Dispose();
    }
}
