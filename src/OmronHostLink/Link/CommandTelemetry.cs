using System.Diagnostics;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The telemetry of one command over all its attempts: one duration measurement and one span
/// (<see cref="HostLinkActivities"/>) from the call to its result or final error, each retry counted. Telemetry is per
/// command, not per attempt.
/// </summary>
internal readonly struct CommandTelemetry
{
    private readonly HostLinkInstruments _instruments;
    private readonly TimeProvider _time;
    private readonly string _link;
    private readonly int _unit;
    private readonly string _command;
    private readonly long _started;
    private readonly Activity? _activity;

    public CommandTelemetry(HostLinkInstruments instruments, TimeProvider time, string link, IHostLinkTransport transport, in HostLinkRequest request)
    {
        _instruments = instruments;
        _time = time;
        _link = link;
        _unit = request.Unit;
        _command = request.Header;
        _started = time.GetTimestamp();
        _activity = HostLinkActivities.Start(request, link, transport);
        Frames = _activity is null ? null : new FrameTally();
    }

    /// <summary>Where the span's frames are counted; null when no span is recorded.</summary>
    public FrameTally? Frames { get; }

    /// <summary>The time since the call.</summary>
    public TimeSpan Elapsed => _time.GetElapsedTime(_started);

    public void Retried(Exception failure) => _instruments.Retry(_link, _unit, _command, failure);

    public void Succeeded(int retries)
    {
        if (_instruments.OperationDuration.Enabled)
        {
            _instruments.Operation(_link, _unit, _command, null, Elapsed);
        }

        if (_activity is not null)
        {
            HostLinkActivities.Succeeded(_activity, Frames!.Sent, Frames.Received, retries);
        }
    }

    public void Failed(Exception failure, int retries)
    {
        if (_instruments.OperationDuration.Enabled)
        {
            _instruments.Operation(_link, _unit, _command, failure, Elapsed);
        }

        if (_activity is not null)
        {
            HostLinkActivities.Failed(_activity, failure, Frames!.Sent, Frames.Received, retries);
        }
    }
}
