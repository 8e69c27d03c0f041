using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Outputs;

namespace OmronHostLink.Gateway.Polling;

/// <summary>
/// Polls every enabled link of the validated options, each through its client (the keyed <see cref="HostLinkClient"/>
/// named after the link, see <see cref="LinkClients"/>), all together until the host stops.
/// </summary>
/// <param name="options">The validated <c>HostLink</c> section.</param>
/// <param name="services">Where the links' clients are.</param>
/// <param name="loggerFactory">For the links' logs.</param>
/// <param name="timeProvider">The clock of intervals, backoff and timestamps.</param>
/// <param name="outputs">The outputs (<see cref="OpenLinks"/>, MQTT when configured): each receives what the links read.</param>
internal sealed class PollingHostedService(IOptions<GatewayOptions> options, IServiceProvider services, ILoggerFactory loggerFactory, TimeProvider timeProvider, IEnumerable<ITagOutput> outputs)
    : BackgroundService
{
    /// <inheritdoc/>
    protected override async Task ExecuteAsync(CancellationToken stoppingToken)
    {
        // Let the host's start return at once: opening a serial port may block.
        await Task.Yield();
        ILogger logger = loggerFactory.CreateLogger<LinkPoller>();
        var sink = new TagOutputs(outputs);
        await Task.WhenAll(options.Value.Links
            .Where(l => l.Value.Enabled)
            .OrderBy(l => l.Key, StringComparer.OrdinalIgnoreCase)
            .Select(l => new LinkPoller(l.Key, l.Value, () => services.GetRequiredKeyedService<HostLinkClient>(l.Key), logger, timeProvider, sink).RunAsync(stoppingToken)))
            .ConfigureAwait(false);
    }
}
