using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Worker.Configuration;
using OmronHostLink.Worker.Mqtt;

namespace OmronHostLink.Worker.Polling;

/// <summary>
/// Polls every enabled link of the validated options, each through its client (the keyed <see cref="HostLinkClient"/>
/// named after the link, see <see cref="LinkClients"/>), all together until the host stops.
/// </summary>
/// <param name="options">The validated <c>HostLink</c> section.</param>
/// <param name="services">Where the links' clients are.</param>
/// <param name="loggerFactory">For the links' logs.</param>
/// <param name="timeProvider">The clock of intervals, backoff and timestamps.</param>
/// <param name="sink">The MQTT output when configured: it receives what the links read.</param>
public sealed class PollingHostedService(IOptions<WorkerOptions> options, IServiceProvider services, ILoggerFactory loggerFactory, TimeProvider timeProvider, ITagSink? sink = null)
    : BackgroundService
{
    /// <inheritdoc/>
    protected override async Task ExecuteAsync(CancellationToken stoppingToken)
    {
        // Let the host's start return at once: opening a serial port may block.
        await Task.Yield();
        ILogger logger = loggerFactory.CreateLogger<LinkPoller>();
        await Task.WhenAll(options.Value.Links
            .Where(l => l.Value.Enabled)
            .OrderBy(l => l.Key, StringComparer.OrdinalIgnoreCase)
            .Select(l => new LinkPoller(l.Key, l.Value, () => services.GetRequiredKeyedService<HostLinkClient>(l.Key), logger, timeProvider, sink).RunAsync(stoppingToken)))
            .ConfigureAwait(false);
    }
}
