using System.Globalization;
using System.Text.Json;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Options;
using OmronHostLink.Gateway.Queue;
using OmronHostLink.Gateway.Statistics;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// Publishes the statistics of every link and PLC unit as retained JSON: a unit's on
/// <c>{prefix}/{link}/status/{unit}</c>, the link's totals on <c>{prefix}/{link}/status/statistics</c>, every
/// <c>Mqtt:StatisticsInterval</c> and at once when a unit's state changes (comm-error, demoted, online). A topic whose
/// last figures still wait in the queue (the broker is away) is not queued again: only the newest figures matter.
/// </summary>
internal sealed class StatisticsPublisher : BackgroundService
{
    /// <summary>The last level of a link's statistics topic (a unit number never is).</summary>
    public const string StatisticsLevel = "statistics";

    private readonly LinkStatistics _statistics;
    private readonly MqttTopics _topics;
    private readonly OutboundQueue _queue;
    private readonly TimeSpan _interval;
    private readonly TimeProvider _time;

    /// <summary>Creates the publisher.</summary>
    public StatisticsPublisher(LinkStatistics statistics, MqttTopics topics, OutboundQueue queue, IOptions<MqttOptions> options, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(statistics);
        ArgumentNullException.ThrowIfNull(options);
        _statistics = statistics;
        _topics = topics;
        _queue = queue;
        _interval = options.Value.StatisticsInterval;
        _time = time;
    }

    /// <summary>The topic of a link's totals.</summary>
    public string LinkTopic(string link) => $"{_topics.LinkStatus(link)}/{StatisticsLevel}";

    /// <summary>The topic of a unit's figures.</summary>
    public string UnitTopic(string link, int unit) => $"{_topics.LinkStatus(link)}/{unit.ToString(CultureInfo.InvariantCulture)}";

    /// <inheritdoc/>
    protected override async Task ExecuteAsync(CancellationToken stoppingToken)
    {
        _statistics.UnitStateChanged += PublishUnit;
        try
        {
            using var timer = new PeriodicTimer(_interval, _time);
            do
            {
                PublishAll();
            }
            while (await timer.WaitForNextTickAsync(stoppingToken).ConfigureAwait(false));
        }
        catch (OperationCanceledException) when (stoppingToken.IsCancellationRequested)
        {
            // Stopping.
        }
        finally
        {
            _statistics.UnitStateChanged -= PublishUnit;
        }
    }

    private void PublishAll()
    {
        foreach (UnitStatistics unit in _statistics.Units())
        {
            Enqueue(UnitTopic(unit.Link, unit.Unit!.Value), unit, always: false);
        }

        foreach (string link in _statistics.LinkNames())
        {
            Enqueue(LinkTopic(link), _statistics.Link(link), always: false);
        }
    }

    private void PublishUnit(string link, int unit)
    {
        if (_statistics.Unit(link, unit) is { } figures)
        {
            Enqueue(UnitTopic(link, unit), figures, always: true);
            Enqueue(LinkTopic(link), _statistics.Link(link), always: true);
        }
    }

    private void Enqueue(string topic, UnitStatistics figures, bool always)
    {
        // A state change is always queued (in order with the tag values it explains); periodic figures only when the
        // topic has nothing waiting.
        if (!always && _queue.HasPending(topic))
        {
            return;
        }

        _queue.Enqueue(new OutboundMessage(topic, JsonSerializer.SerializeToUtf8Bytes(figures, StatisticsJsonContext.Default.UnitStatistics), Retain: true));
    }
}
