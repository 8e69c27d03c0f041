using System.Text;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The MQTT connection and the one publisher loop. It connects (MQTT 5, last will <c>offline</c> on the worker's
/// status topic), announces <c>online</c>, republishes the current state of topics with nothing queued, then sends the
/// queue in order, removing each message only once the broker has acknowledged it. When the broker goes away it
/// reconnects with capped exponential backoff, and the queue keeps filling meanwhile. On a clean stop it sends what is
/// queued (for a few seconds at most), publishes <c>offline</c> and disconnects.
/// </summary>
internal sealed class MqttGateway : IHostedService, IAsyncDisposable
{
    /// <summary>The worker's status while connected (the birth message).</summary>
    public const string Online = "online";

    /// <summary>The worker's status when it is gone (the last will, or a clean stop).</summary>
    public const string Offline = "offline";

    private static readonly TimeSpan DrainLimit = TimeSpan.FromSeconds(5);

    private readonly MqttOptions _options;
    private readonly MqttTopics _topics;
    private readonly OutboundQueue _queue;
    private readonly MqttTagSink _sink;
    private readonly TagCatalog _catalog;
    private readonly MqttMetrics _metrics;
    private readonly MqttClientFactory _factory;
    private readonly MqttBrokerConnection _connection;
    private readonly WriteCommandProcessor _writes;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly HashSet<string> _refusedTopics = new(StringComparer.Ordinal);
    private MqttClientOptions? _clientOptions;
    private volatile bool _stopping;
    private int _stopCalls;
    private bool _everConnected;
    private long _overflowSince;

    /// <summary>Creates the gateway; nothing connects until it is started.</summary>
    public MqttGateway(
        IOptions<MqttOptions> options,
        MqttTopics topics,
        OutboundQueue queue,
        MqttTagSink sink,
        TagCatalog catalog,
        MqttMetrics metrics,
        MqttClientFactory factory,
        WriteCommandProcessor writes,
        ILogger<MqttGateway> logger,
        TimeProvider timeProvider)
    {
        ArgumentNullException.ThrowIfNull(options);
        _options = options.Value;
        _topics = topics;
        _queue = queue;
        _sink = sink;
        _catalog = catalog;
        _metrics = metrics;
        _factory = factory;
        _writes = writes;
        _logger = logger;
        _time = timeProvider;
        _connection = new MqttBrokerConnection(_options, MqttOptions.SectionName, factory, timeProvider);
    }

    /// <summary>Whether the client is connected to the broker now.</summary>
    public bool IsConnected => _connection.Client.IsConnected;

    /// <inheritdoc/>
    public Task StartAsync(CancellationToken cancellationToken)
    {
        if (_options.Tls is { Enabled: true, AllowUntrustedCertificates: true })
        {
            MqttLog.UntrustedCertificates(_logger, _connection.Broker);
        }

        _clientOptions = ClientOptions();
        IMqttClient client = _connection.Client;
        client.DisconnectedAsync += _ =>
        {
            _queue.Wake();
            return Task.CompletedTask;
        };
        client.ApplicationMessageReceivedAsync += e =>
        {
            _writes.Accept(e.ApplicationMessage);
            return Task.CompletedTask;
        };
        _queue.OverflowStarted += OnOverflowStarted;
        if (_options.Writes.Enabled)
        {
            _connection.Start(RunAsync, _writes.RunAsync);
        }
        else
        {
            _connection.Start(RunAsync);
        }

        return Task.CompletedTask;
    }

    /// <inheritdoc/>
    public async Task StopAsync(CancellationToken cancellationToken)
    {
        if (_connection.ConnectionLoop is not { } loop || Interlocked.Exchange(ref _stopCalls, 1) != 0)
        {
            return;
        }

        // The links stop first (they are registered after this service) and queue their offline states; send them
        // if the broker is there. If it is not, there is nothing to wait for: the queue stays in the durable queue for the
        // next run, or is lost with the process and the next run announces how many (OutboundQueueStore).
        _stopping = true;
        _queue.Wake();
        if (!IsConnected)
        {
            await _connection.CancelAsync().ConfigureAwait(false);
        }

        using (var drain = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken))
        {
            drain.CancelAfter(DrainLimit);
            await loop.WaitAsync(drain.Token).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }

        await _connection.StopLoopsAsync().ConfigureAwait(false);
        EndOverflow(_queue.EndOverflowEpisode());
        // If the broker goes away meanwhile, its last will says offline instead.
        await _connection.CloseAsync((client, ct) => client.PublishAsync(Message(new OutboundMessage(_topics.WorkerStatus, Encoding.UTF8.GetBytes(Offline), Retain: true)), ct)).ConfigureAwait(false);
        MqttLog.Stopped(_logger, _queue.Count);
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => _connection.DisposeAsync();

    /// <summary>MQTT 5, a clean start and the last will <c>offline</c> on the worker's status topic.</summary>
    private MqttClientOptions ClientOptions()
        => _connection.ClientOptions()
            .WithProtocolVersion(MqttProtocolVersion.V500)
            // No session kept by the broker: the worker's queue is the only store, and no stale command is delivered
            // after a reconnection.
            .WithCleanStart(true)
            .WithWillTopic(_topics.WorkerStatus)
            .WithWillPayload(Encoding.UTF8.GetBytes(Offline))
            .WithWillRetain(true)
            .WithWillQualityOfServiceLevel(MqttClientOptionsFactory.QualityOfService(_options.QoS))
            .Build();

    private async Task RunAsync(CancellationToken cancellationToken)
    {
        IMqttClient client = _connection.Client;
        long outageSince = 0;
        while (!cancellationToken.IsCancellationRequested)
        {
            try
            {
                if (!client.IsConnected)
                {
                    if (_stopping)
                    {
                        return;
                    }

                    await ConnectAsync(client, cancellationToken).ConfigureAwait(false);
                    if (_connection.FailedAttempts > 0)
                    {
                        MqttLog.Reconnected(_logger, _connection.Broker, _time.GetElapsedTime(outageSince).TotalSeconds, _connection.FailedAttempts, _queue.Count);
                    }
                    else if (!_everConnected)
                    {
                        MqttLog.Connected(_logger, _connection.Broker, _options.ClientIdOrDefault, _topics.Prefix);
                    }

                    _everConnected = true;
                    _connection.Connected();
                    continue;
                }

                if (!_queue.TryPeek(out OutboundMessage? message))
                {
                    if (_stopping)
                    {
                        return;
                    }

                    await _queue.WaitAsync(cancellationToken).ConfigureAwait(false);
                    continue;
                }

                await PublishAsync(client, message, cancellationToken).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
            {
                return;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                // Unreachable, refused, TLS failure, an acknowledgement that did not come: start again from a fresh
                // connection, so nothing half-done on the old one can reorder the queue.
                (string reason, TimeSpan delay) = await _connection.FailedAsync(e).ConfigureAwait(false);
                if (_stopping)
                {
                    return;
                }

                if (_connection.FailedAttempts == 1)
                {
                    outageSince = _time.GetTimestamp();
                    MqttLog.Unreachable(_logger, _connection.Broker, reason, _queue.Count, delay.TotalSeconds, _options.Reconnect.Max.TotalSeconds);
                }
                else
                {
                    MqttLog.StillUnreachable(_logger, _connection.Broker, reason, delay.TotalSeconds);
                }

                if (!await _connection.DelayAsync(delay).ConfigureAwait(false))
                {
                    return;
                }
            }
        }
    }

    private async Task ConnectAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        MqttClientConnectResult result = await client.ConnectAsync(_clientOptions!, cancellationToken).ConfigureAwait(false);
        if (result.ResultCode != MqttClientConnectResultCode.Success)
        {
            string hint = result.ResultCode is MqttClientConnectResultCode.BadUserNameOrPassword or MqttClientConnectResultCode.NotAuthorized
                ? "; check Mqtt:Username, Mqtt:Password and the broker's users and ACL"
                : "";
            throw new InvalidOperationException($"the broker refused the connection: {result.ResultCode}{(string.IsNullOrEmpty(result.ReasonString) ? "" : " " + result.ReasonString)}{hint}");
        }

        _metrics.Connected();
        if (_options.Writes.Enabled)
        {
            await SubscribeCommandsAsync(client, cancellationToken).ConfigureAwait(false);
        }

        // Birth first, then the state of every topic with nothing queued (a restarted broker may have lost it).
        await PublishNowAsync(client, new OutboundMessage(_topics.WorkerStatus, Encoding.UTF8.GetBytes(Online), Retain: true), cancellationToken).ConfigureAwait(false);
        foreach (OutboundMessage message in _sink.Snapshot())
        {
            await PublishNowAsync(client, message, cancellationToken).ConfigureAwait(false);
        }
    }

    private async Task SubscribeCommandsAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        MqttClientSubscribeOptionsBuilder builder = _factory.CreateSubscribeOptionsBuilder();
        var filters = new List<string>();
        foreach (string link in _catalog.Links)
        {
            string filter = _topics.CommandFilter(link);
            filters.Add(filter);
            builder = builder.WithTopicFilter(f => f
                .WithTopic(filter)
                .WithQualityOfServiceLevel(MqttClientOptionsFactory.QualityOfService(Math.Max(_options.QoS, 1)))
                .WithNoLocal(true)
                // A retained command would be carried out again for every new subscriber: never take one. The broker
                // does not send the stored ones, and keeps the retain flag on the ones it forwards live (MQTT 5 "retain
                // as published"; without it a live retained command arrives looking like any other).
                .WithRetainHandling(MqttRetainHandling.DoNotSendOnSubscribe)
                .WithRetainAsPublished(true));
        }

        MqttClientSubscribeResult result = await client.SubscribeAsync(builder.Build(), cancellationToken).ConfigureAwait(false);
        foreach (MqttClientSubscribeResultItem item in result.Items)
        {
            if (item.ResultCode > MqttClientSubscribeResultCode.GrantedQoS2)
            {
                MqttLog.SubscribeRefused(_logger, item.TopicFilter.Topic, item.ResultCode.ToString());
            }
        }

        MqttLog.WritesAccepted(_logger, _catalog.Tags.Count(t => t.Writable), string.Join(", ", filters));
    }

    private async Task PublishAsync(IMqttClient client, OutboundMessage message, CancellationToken cancellationToken)
    {
        await PublishNowAsync(client, message, cancellationToken).ConfigureAwait(false);
        EndOverflow(_queue.Remove(message));
    }

    private async Task PublishNowAsync(IMqttClient client, OutboundMessage message, CancellationToken cancellationToken)
    {
        MqttClientPublishResult result = await client.PublishAsync(Message(message), cancellationToken).ConfigureAwait(false);
        if (result.ReasonCode is MqttClientPublishReasonCode.Success or MqttClientPublishReasonCode.NoMatchingSubscribers)
        {
            _metrics.Published();
        }
        else if (_refusedTopics.Add(message.Topic))
        {
            // Acknowledged with a refusal (an ACL, a quota): sending it again would get the same answer.
            MqttLog.PublishRefused(_logger, message.Topic, result.ReasonCode.ToString(), string.IsNullOrEmpty(result.ReasonString) ? "" : ": " + result.ReasonString);
        }
    }

    private MqttApplicationMessage Message(OutboundMessage message)
    {
        MqttApplicationMessageBuilder builder = _factory.CreateApplicationMessageBuilder()
            .WithTopic(message.Topic)
            .WithPayload(message.Payload)
            .WithRetainFlag(message.Retain)
            .WithQualityOfServiceLevel(MqttClientOptionsFactory.QualityOfService(_options.QoS))
            .WithPayloadFormatIndicator(MqttPayloadFormatIndicator.CharacterData);
        if (message.CorrelationData is { } correlation)
        {
            builder = builder.WithCorrelationData(correlation);
        }

        return builder.Build();
    }

    private void OnOverflowStarted()
    {
        Interlocked.Exchange(ref _overflowSince, _time.GetTimestamp());
        MqttLog.QueueOverflowing(_logger, _queue.Capacity);
    }

    private void EndOverflow(long dropped)
    {
        if (dropped > 0)
        {
            MqttLog.QueueOverflowed(_logger, dropped, _queue.Capacity, _time.GetElapsedTime(Interlocked.Read(ref _overflowSince)).TotalSeconds);
        }
    }
}
