using System.Buffers;
using System.Threading.Channels;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;
using OmronHostLink.Gateway.Broker;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's MQTT session (Sparkplug B 3.0): it connects with the NDEATH of a new <c>bdSeq</c> as its will,
/// subscribes to its NCMD and DCMD topics, publishes NBIRTH and the DBIRTH of every answering unit, then the node's
/// deaths, births and data as <see cref="SparkplugNode"/> gives them, in order, one publisher. An NCMD
/// <c>Node Control/Rebirth</c> is answered with new births; a DCMD is handed to the <see cref="SparkplugCommands"/>.
/// When the broker goes away it reconnects with capped exponential backoff (a new <c>bdSeq</c>, new births; data meanwhile
/// is not kept, a host application reads the state from the births). On a clean stop it publishes NDEATH itself.
/// Births and data go out at QoS 0, not retained; NDEATH at QoS 1, as the specification asks.
/// With <see cref="SparkplugOptions.PrimaryHostId"/> it also subscribes to the primary host application's STATE before
/// anything else, and publishes the births only once a STATE on that connection says the host is online; a STATE saying
/// it is offline ends the session (NDEATH, disconnect) and the node reconnects after the backoff and waits again.
/// Meanwhile the node keeps the latest values, and the births that follow carry them.
/// </summary>
internal sealed class SparkplugEdgeNode : IHostedService, IAsyncDisposable
{
    private readonly SparkplugOptions _options;
    private readonly SparkplugNode _node;
    private readonly SparkplugCommands _commands;
    private readonly MqttClientFactory _factory = new();
    private readonly MqttBrokerConnection _connection;
    private readonly ILogger _logger;
    private readonly SparkplugPrimaryHost? _primaryHost;
    private readonly Channel<bool> _wake = Channel.CreateBounded<bool>(new BoundedChannelOptions(1) { FullMode = BoundedChannelFullMode.DropWrite });
    private ulong _bdSeq;
    private int _connections;

    /// <summary>Creates the edge node; nothing connects until it is started.</summary>
    public SparkplugEdgeNode(IOptions<SparkplugOptions> options, SparkplugNode node, SparkplugCommands commands, ILogger<SparkplugEdgeNode> logger, TimeProvider timeProvider)
    {
        ArgumentNullException.ThrowIfNull(options);
        _options = options.Value;
        _node = node;
        _commands = commands;
        _logger = logger;
        _connection = new MqttBrokerConnection(_options, SparkplugOptions.SectionName, _factory, timeProvider);
        _primaryHost = string.IsNullOrEmpty(_options.PrimaryHostId) ? null : new SparkplugPrimaryHost(_options.PrimaryHostId);
    }

    /// <summary>Whether the session is up (connected, births sent).</summary>
    public bool IsOnline { get; private set; }

    /// <inheritdoc/>
    public Task StartAsync(CancellationToken cancellationToken)
    {
        if (_options.Tls is { Enabled: true, AllowUntrustedCertificates: true })
        {
            SparkplugLog.UntrustedCertificates(_logger, _connection.Broker);
        }

        IMqttClient client = _connection.Client;
        client.DisconnectedAsync += _ =>
        {
            Wake();
            return Task.CompletedTask;
        };
        client.ApplicationMessageReceivedAsync += e =>
        {
            Received(e.ApplicationMessage);
            return Task.CompletedTask;
        };
        _node.Changed += Wake;
        _connection.Start(RunAsync, _commands.RunAsync);
        return Task.CompletedTask;
    }

    /// <inheritdoc/>
    public async Task StopAsync(CancellationToken cancellationToken)
    {
        if (_connection.ConnectionLoop is null || _connection.IsStopping)
        {
            return;
        }

        _node.Changed -= Wake;
        await _connection.StopLoopsAsync().ConfigureAwait(false);

        // The links have stopped (they are registered after this service): their devices' deaths go out, then NDEATH.
        // If the broker goes away meanwhile, it publishes the will, the same NDEATH.
        if (IsOnline)
        {
            await _connection.CloseAsync(async (client, ct) =>
            {
                await PublishPendingAsync(client, ct).ConfigureAwait(false);
                await client.PublishAsync(NodeDeath(), ct).ConfigureAwait(false);
            }).ConfigureAwait(false);
        }

        IsOnline = false;
        SparkplugLog.Stopped(_logger, _connection.Broker);
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => _connection.DisposeAsync();

    private void Wake() => _wake.Writer.TryWrite(true);

    private void Received(MqttApplicationMessage message)
    {
        if (_primaryHost is not null && message.Topic == _primaryHost.Topic)
        {
            if (_primaryHost.Take(message.Payload.ToArray()) is { } why)
            {
                SparkplugLog.StateIgnored(_logger, message.Topic, why);
            }

            Wake();
            return;
        }

        if (!SparkplugTopic.TryParse(message.Topic, out SparkplugTopic? topic) || topic!.GroupId != _node.GroupId || topic.EdgeNodeId != _node.EdgeNodeId)
        {
            return;
        }

        if (topic.Type == SparkplugMessageType.NCMD)
        {
            IReadOnlyList<SparkplugCommandMetric>? metrics = SparkplugCommandMetric.Parse(message.Payload.ToArray());
            if (metrics is not null && metrics.Any(m => m.Name == SparkplugPayloads.Rebirth && m.TryGetValue(SparkplugDataType.Boolean, out System.Text.Json.JsonElement v, out _) && v.GetBoolean()))
            {
                SparkplugLog.RebirthRequested(_logger);
                _node.RequestRebirth();
            }
            else
            {
                SparkplugLog.CommandIgnored(_logger, message.Topic, "an NCMD other than Node Control/Rebirth = true");
            }
        }
        else if (topic.Type == SparkplugMessageType.DCMD && topic.DeviceId is { } device)
        {
            _commands.Accept(device, message.Payload.ToArray());
        }
    }

    private async Task RunAsync(CancellationToken cancellationToken)
    {
        IMqttClient client = _connection.Client;
        while (!cancellationToken.IsCancellationRequested)
        {
            try
            {
                if (!client.IsConnected)
                {
                    IsOnline = false;
                    await ConnectAsync(client, cancellationToken).ConfigureAwait(false);
                    if (_primaryHost is null)
                    {
                        await BirthAsync(client, cancellationToken).ConfigureAwait(false);
                    }
                    else
                    {
                        SparkplugLog.WaitingForPrimaryHost(_logger, _connection.Broker, _bdSeq, _primaryHost.HostId, _primaryHost.Topic);
                    }

                    _connection.Connected();
                    continue;
                }

                if (_primaryHost is not null)
                {
                    if (IsOnline && !_primaryHost.IsOnline)
                    {
                        if (!await EndSessionAsync(_primaryHost).ConfigureAwait(false))
                        {
                            return;
                        }

                        continue;
                    }

                    if (!IsOnline)
                    {
                        if (_primaryHost.IsOnline)
                        {
                            SparkplugLog.PrimaryHostOnline(_logger, _primaryHost.HostId, _primaryHost.Timestamp);
                            await BirthAsync(client, cancellationToken).ConfigureAwait(false);
                        }
                        else
                        {
                            // Waiting: the node keeps taking values; the births that follow carry the latest.
                            await _wake.Reader.ReadAsync(cancellationToken).ConfigureAwait(false);
                        }

                        continue;
                    }
                }

                if (_node.RebirthRequested)
                {
                    await PublishAllAsync(client, _node.Births(_bdSeq), cancellationToken).ConfigureAwait(false);
                    continue;
                }

                await PublishPendingAsync(client, cancellationToken).ConfigureAwait(false);
                await _wake.Reader.ReadAsync(cancellationToken).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
            {
                return;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                IsOnline = false;
                (string reason, TimeSpan delay) = await _connection.FailedAsync(e).ConfigureAwait(false);
                _node.TakeMessages(connected: false);
                SparkplugLog.Unreachable(_logger, _connection.Broker, reason, delay.TotalSeconds);
                if (!await _connection.DelayAsync(delay).ConfigureAwait(false))
                {
                    return;
                }
            }
        }
    }

    /// <summary>Connects with the will of a new bdSeq and subscribes to the commands (and the primary host's STATE).</summary>
    private async Task ConnectAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        // A new bdSeq for every connection: the will registered now carries it, and so does the NBIRTH that follows.
        _bdSeq = (ulong)(_connections++ % 256);
        _primaryHost?.Connecting();
        MqttClientConnectResult result = await client.ConnectAsync(ClientOptions(_bdSeq), cancellationToken).ConfigureAwait(false);
        if (result.ResultCode != MqttClientConnectResultCode.Success)
        {
            throw new InvalidOperationException($"the broker refused the connection: {result.ResultCode}");
        }

        MqttClientSubscribeOptionsBuilder subscribe = _factory.CreateSubscribeOptionsBuilder()
            .WithTopicFilter(f => f.WithTopic(_node.Topic(SparkplugMessageType.NCMD).ToString()).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce))
            .WithTopicFilter(f => f.WithTopic(_node.Topic(SparkplugMessageType.DCMD, "+").ToString()).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce));
        if (_primaryHost is not null)
        {
            // The broker answers with the retained STATE: the host's state for this connection.
            subscribe = subscribe.WithTopicFilter(f => f.WithTopic(_primaryHost.Topic).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce));
        }

        await client.SubscribeAsync(subscribe.Build(), cancellationToken).ConfigureAwait(false);
    }

    /// <summary>Publishes NBIRTH and the DBIRTH of every answering unit: the session begins.</summary>
    private async Task BirthAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        List<SparkplugMessage> births = _node.Births(_bdSeq);
        await PublishAllAsync(client, births, cancellationToken).ConfigureAwait(false);
        IsOnline = true;
        SparkplugLog.Online(_logger, _connection.Broker, _node.GroupId, _node.EdgeNodeId, _bdSeq, births.Count - 1);
    }

    /// <summary>
    /// The primary host went offline: NDEATH of the session's bdSeq, then a clean disconnect (so the broker drops the
    /// will), then the backoff before the next connection. False when the node is stopped meanwhile.
    /// </summary>
    private async Task<bool> EndSessionAsync(SparkplugPrimaryHost host)
    {
        await _connection.CloseAsync((client, ct) => client.PublishAsync(NodeDeath(), ct)).ConfigureAwait(false);
        IsOnline = false;
        _node.TakeMessages(connected: false);
        TimeSpan delay = _connection.Backoff();
        SparkplugLog.PrimaryHostOffline(_logger, host.HostId, host.Timestamp, _bdSeq, _connection.Broker, delay.TotalSeconds);
        return await _connection.DelayAsync(delay).ConfigureAwait(false);
    }

    private async Task PublishPendingAsync(IMqttClient client, CancellationToken cancellationToken)
        => await PublishAllAsync(client, _node.TakeMessages(connected: true), cancellationToken).ConfigureAwait(false);

    private async Task PublishAllAsync(IMqttClient client, List<SparkplugMessage> messages, CancellationToken cancellationToken)
    {
        foreach (SparkplugMessage message in messages)
        {
            await client.PublishAsync(Message(message.Topic, message.Payload, MqttQualityOfServiceLevel.AtMostOnce), cancellationToken).ConfigureAwait(false);
        }
    }

    /// <summary>The session's NDEATH, sent by the node itself (QoS 1).</summary>
    private MqttApplicationMessage NodeDeath()
        => Message(_node.Topic(SparkplugMessageType.NDEATH), SparkplugPayloads.NodeDeath(_bdSeq), MqttQualityOfServiceLevel.AtLeastOnce);

    private MqttApplicationMessage Message(SparkplugTopic topic, byte[] payload, MqttQualityOfServiceLevel qos)
        => _factory.CreateApplicationMessageBuilder()
            .WithTopic(topic.ToString())
            .WithPayload(payload)
            .WithQualityOfServiceLevel(qos)
            .WithRetainFlag(false)
            .Build();

    /// <summary>MQTT 3.1.1, a clean session and the NDEATH of <paramref name="bdSeq"/> as the will.</summary>
    private MqttClientOptions ClientOptions(ulong bdSeq)
        => _connection.ClientOptions()
            .WithProtocolVersion(MqttProtocolVersion.V311)
            .WithCleanSession(true)
            .WithWillTopic(_node.Topic(SparkplugMessageType.NDEATH).ToString())
            .WithWillPayload(SparkplugPayloads.NodeDeath(bdSeq))
            .WithWillQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce)
            .WithWillRetain(false)
            .Build();
}
