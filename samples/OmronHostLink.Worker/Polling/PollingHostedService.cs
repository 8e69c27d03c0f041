using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using OmronHostLink.Worker.Configuration;
using OmronHostLink.Worker.Mqtt;

namespace OmronHostLink.Worker.Polling;

/// <summary>
/// Starts one <see cref="LinkPollingService"/> (a <see cref="BackgroundService"/>) per enabled link in the validated
/// options, and stops them all together. Links come from configuration, so they cannot be registered one by one
/// before the configuration is complete; this keeps the host's registration independent of it.
/// </summary>
public sealed class PollingHostedService : IHostedService, IDisposable
{
    private readonly IOptions<WorkerOptions> _options;
    private readonly ILoggerFactory _loggerFactory;
    private readonly TimeProvider _time;
    private readonly List<LinkPollingService> _links = new();
    private readonly ITagSink? _sink;

    /// <summary>Creates the service; <paramref name="sink"/> (the MQTT output, when configured) receives what the links read.</summary>
    public PollingHostedService(IOptions<WorkerOptions> options, ILoggerFactory loggerFactory, TimeProvider timeProvider, ITagSink? sink = null)
    {
        _options = options;
        _loggerFactory = loggerFactory;
        _time = timeProvider;
        _sink = sink;
    }

    /// <summary>The links being polled.</summary>
    public IReadOnlyList<LinkPollingService> Links => _links;

    /// <inheritdoc/>
    public async Task StartAsync(CancellationToken cancellationToken)
    {
        // Reading Value validates the options (it throws OptionsValidationException naming the bad fields).
        WorkerOptions options = _options.Value;
        foreach ((string name, LinkOptions link) in options.Links.OrderBy(l => l.Key, StringComparer.OrdinalIgnoreCase))
        {
            if (!link.Enabled)
            {
                continue;
            }

            var service = new LinkPollingService(name, link, _loggerFactory, _time, _sink);
            _links.Add(service);
            await service.StartAsync(cancellationToken).ConfigureAwait(false);
        }
    }

    /// <inheritdoc/>
    public Task StopAsync(CancellationToken cancellationToken)
        => Task.WhenAll(_links.Select(l => l.StopAsync(cancellationToken)));

    /// <inheritdoc/>
    public void Dispose()
    {
        foreach (LinkPollingService link in _links)
        {
            link.Dispose();
        }
    }
}
