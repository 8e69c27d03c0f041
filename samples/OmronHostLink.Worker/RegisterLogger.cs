using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Planning;

namespace OmronHostLink.Samples.Worker;

/// <summary>
/// Watches each configured client's tags (<c>WatchAsync</c>:
/// one planned read a cycle) and logs every change, outage and recovery as a structured log entry.
/// </summary>
internal sealed partial class RegisterLogger(IOptions<WatchList> watches, IServiceProvider services, ILogger<RegisterLogger> logger) : BackgroundService
{
    protected override Task ExecuteAsync(CancellationToken stoppingToken)
        => Task.WhenAll(watches.Value.Select(w => WatchAsync(w.Key, w.Value, stoppingToken)));

    private async Task WatchAsync(string client, WatchSettings settings, CancellationToken stoppingToken)
    {
        // Let the host finish starting: the first read may wait for a serial port or a TCP connection.
        await Task.Yield();
        HostLinkClient plc = services.GetRequiredKeyedService<HostLinkClient>(client);
        PlcTag[] tags = settings.Tags.Select(t => PlcTag.Parse(t)).ToArray();
        var options = new WatchOptions { Interval = settings.Interval, MaxRetryInterval = TimeSpan.FromSeconds(30) };
        LogWatching(logger, client, plc.Description, tags.Length, settings.Interval.TotalMilliseconds);
        try
        {
            // Outages do not end a watch: it reports them and keeps retrying with a growing delay.
            await foreach (WatchEvent e in plc.WatchAsync(tags, options, stoppingToken).ConfigureAwait(false))
            {
                switch (e.Kind)
                {
                    case WatchEventKind.Changed:
                        LogChanged(logger, client, settings.Tags[e.TagIndex], e.NewValue.ToObject(), e.OldValue?.ToObject());
                        break;
                    case WatchEventKind.Outage:
                        LogOutage(logger, client, e.Exception!.Message, e.RetryDelay.TotalSeconds);
                        break;
                    case WatchEventKind.Resumed:
                        LogResumed(logger, client, e.Duration.TotalSeconds);
                        break;
                    case WatchEventKind.Overrun:
                        LogOverrun(logger, client, e.Duration.TotalMilliseconds, settings.Interval.TotalMilliseconds);
                        break;
                }
            }
        }
        catch (OperationCanceledException) when (stoppingToken.IsCancellationRequested)
        {
            // Stopping.
        }
    }

    [LoggerMessage(EventId = 1, Level = LogLevel.Information, Message = "{Client}: watching {TagCount} tags on {Link} every {IntervalMs} ms")]
    private static partial void LogWatching(ILogger logger, string client, string link, int tagCount, double intervalMs);

    [LoggerMessage(EventId = 2, Level = LogLevel.Information, Message = "{Client} {Tag} = {Value} (was {OldValue})")]
    private static partial void LogChanged(ILogger logger, string client, string tag, object value, object? oldValue);

    [LoggerMessage(EventId = 3, Level = LogLevel.Warning, Message = "{Client}: no answer ({Reason}); retrying in {RetrySeconds} s")]
    private static partial void LogOutage(ILogger logger, string client, string reason, double retrySeconds);

    [LoggerMessage(EventId = 4, Level = LogLevel.Information, Message = "{Client}: answering again after {OutageSeconds:0.0} s")]
    private static partial void LogResumed(ILogger logger, string client, double outageSeconds);

    [LoggerMessage(EventId = 5, Level = LogLevel.Warning, Message = "{Client}: a poll took {CycleMs:0} ms, longer than the interval of {IntervalMs} ms")]
    private static partial void LogOverrun(ILogger logger, string client, double cycleMs, double intervalMs);
}
