using System.Collections.Concurrent;
using System.Diagnostics;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The library's activity source, <see cref="HostLinkTelemetry.ActivitySourceName"/>: one client span per command (not
/// per attempt) with the command, unit, link, frames, retries and end code. Nothing is made unless a listener samples
/// the span.
/// </summary>
internal static class HostLinkActivities
{
    private const string NormalCompletion = "00";

    public static readonly ActivitySource Source = new(HostLinkTelemetry.ActivitySourceName, HostLinkInstruments.Version);

    // Span names by header ("HostLink RD"): a few dozen headers, each name made once.
    private static readonly ConcurrentDictionary<string, string> Names = new(StringComparer.Ordinal);

    /// <summary>
    /// Starts the span of one command, or returns null when nobody listens, without touching anything that allocates
    /// (a serial transport's description is made on each read of it).
    /// </summary>
    public static Activity? Start(in HostLinkRequest request, string link, IHostLinkTransport transport)
    {
        if (!Source.HasListeners())
        {
            return null;
        }

        Activity? activity = Source.StartActivity(Names.GetOrAdd(request.Header, static header => "HostLink " + header), ActivityKind.Client);
        if (activity is { IsAllDataRequested: true })
        {
            activity.SetTag(TelemetryTags.Command, request.Header);
            activity.SetTag(TelemetryTags.Unit, HostLinkInstruments.Boxed(request.Unit));
            activity.SetTag(TelemetryTags.LinkName, link);
            activity.SetTag(TelemetryTags.Transport, transport.Description);
        }

        return activity;
    }

    /// <summary>Ends the span of a command that was answered with end code 00.</summary>
    public static void Succeeded(Activity activity, int framesSent, int framesReceived, int retries)
    {
        if (activity.IsAllDataRequested)
        {
            Counts(activity, framesSent, framesReceived, retries);
            activity.SetTag(TelemetryTags.EndCode, NormalCompletion);
        }

        activity.Dispose();
    }

    /// <summary>Ends the span of a failed command: status Error, <c>error.type</c>, the end code if one came, the exception.</summary>
    public static void Failed(Activity activity, Exception failure, int framesSent, int framesReceived, int retries)
    {
        activity.SetStatus(ActivityStatusCode.Error, failure.Message);
        if (activity.IsAllDataRequested)
        {
            Counts(activity, framesSent, framesReceived, retries);
            activity.SetTag(TelemetryTags.ErrorType, ErrorTypes.Of(failure));
            if (failure is EndCodeException e)
            {
                activity.SetTag(TelemetryTags.EndCode, e.FrameEndCode);
                if (e.CarriedEndCode is { } carried)
                {
                    activity.SetTag(TelemetryTags.FinsEndCode, carried);
                }
            }

            activity.AddException(failure);
        }

        activity.Dispose();
    }

    private static void Counts(Activity activity, int framesSent, int framesReceived, int retries)
    {
        activity.SetTag(TelemetryTags.FramesSent, HostLinkInstruments.Boxed(framesSent));
        activity.SetTag(TelemetryTags.FramesReceived, HostLinkInstruments.Boxed(framesReceived));
        activity.SetTag(TelemetryTags.Retries, HostLinkInstruments.Boxed(retries));
    }
}
