using System.Buffers;
using System.Diagnostics.Metrics;
using System.Threading.Channels;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Options;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;
using OmronHostLink.Gateway.Broker;
using OmronHostLink.Gateway.Configuration;

namespace OmronHostLink.Gateway.Sparkplug;

/// <summary>
/// The edge node's MQTT session (Sparkplug B 3.0): it connects with the NDEATH of a new <c>bdSeq</c> as its will,
/// subscribes to its NCMD and DCMD topics, publishes NBIRTH and the DBIRTH of every answering unit, then the node's
/// deaths, births and data as <see cref="SparkplugNode"/> gives them, in order, one publisher; between live messages it
/// publishes the changes store-and-forward kept, as history, one message at a time (so live data waits for one publish
/// at most). An NCMD <c>Node Control/Rebirth</c> is answered with new births; a DCMD is handed to the
/// <see cref="SparkplugCommands"/>. When the broker goes away it walks to the next server of its list (one connection at
/// a time), backing off once every server has failed: a new <c>bdSeq</c>, new births, then the history. On a clean stop
/// it publishes NDEATH itself. Births and data go out at QoS 0, not retained; NDEATH at QoS 1, as the specification asks.
/// With <see cref="SparkplugOptions.PrimaryHostId"/> it also subscribes to the primary host application's STATE before
/// anything else, and publishes the births only once a STATE on that connection says the host is online; a STATE saying
/// it is offline ends the session (NDEATH, disconnect) and the node moves to the next server and waits again — with one
/// server, reconnects there after the backoff. With several servers it also leaves a server whose retained STATE says
/// offline, or that has none within <see cref="MqttBrokerOptions.Timeout"/>.
/// </summary>
internal sealed class SparkplugEdgeNode : IHostedService, IAsyncDisposable
{
    private readonly SparkplugOptions _options;
    private readonly SparkplugNode _node;
    private readonly SparkplugCommands _commands;
    private readonly MqttClientFactory _factory = new();
    private readonly MqttBrokerConnection _connection;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly SparkplugPrimaryHost? _primaryHost;
    private readonly Channel<bool> _wake = Channel.CreateBounded<bool>(new BoundedChannelOptions(1) { FullMode = BoundedChannelFullMode.DropWrite });
    private readonly Queue<byte[]> _ownBirths = new();
    private readonly object _birthsGate = new();
    private ulong _bdSeq;
    private int _connections;
    private long _foreignBirths;
    private bool _foreignBirthLogged;

    /// <summary>Creates the edge node; nothing connects until it is started.</summary>
    public SparkplugEdgeNode(
        IOptions<SparkplugOptions> options,
        SparkplugNode node,
        SparkplugCommands commands,
        BrokerConnections connections,
        IMeterFactory meterFactory,
        ILogger<SparkplugEdgeNode> logger,
        TimeProvider timeProvider)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(connections);
        _options = options.Value;
        _node = node;
        _commands = commands;
        _logger = logger;
        _time = timeProvider;
        _connection = new MqttBrokerConnection(_options, SparkplugOptions.SectionName, "Sparkplug", _factory, timeProvider, logger)
        {
            Session = Session,
        };
        connections.Add(_connection);
        _primaryHost = string.IsNullOrEmpty(_options.PrimaryHostId) ? null : new SparkplugPrimaryHost(_options.PrimaryHostId, _options.PrimaryHostLegacyState);
        SparkplugMetrics.Create(meterFactory, node);
    }

    /// <summary>Whether the session is up (connected, births sent).</summary>
    public bool IsOnline { get; private set; }

    /// <summary>The broker connection: the server in use, since when it is connected, its last failure and publish.</summary>
    public MqttBrokerConnection Connection => _connection;

    /// <summary>The primary host application whose online STATE the births wait for; null when they wait for none.</summary>
    public string? PrimaryHostId => _primaryHost?.HostId;

    /// <inheritdoc/>
    public Task StartAsync(CancellationToken cancellationToken)
    {
        foreach (MqttServer server in _connection.Servers.Where(s => s.Tls is { Enabled: true, AllowUntrustedCertificates: true }))
        {
            SparkplugLog.UntrustedCertificates(_logger, server.ToString());
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
        _connection.Start(RunAsync, _commands.RunAsync, _connection.LivenessAsync);
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
                await PublishAllAsync(client, _node.TakeMessages(), ct).ConfigureAwait(false);
                await client.PublishAsync(NodeDeath(), ct).ConfigureAwait(false);
            }).ConfigureAwait(false);
        }

        IsOnline = false;
        _node.SessionEnded(lost: false);
        _connection.Stopped();
        SparkplugLog.Stopped(_logger, _connection.Broker);
    }

    /// <inheritdoc/>
    public ValueTask DisposeAsync() => _connection.DisposeAsync();

    private void Wake() => _wake.Writer.TryWrite(true);

    private BrokerSession Session()
    {
        (int stored, long sent, long dropped) = _node.Store;
        string state = IsOnline ? "online"
            : _connection.Client.IsConnected && _primaryHost is not null ? "waiting for the primary host"
            : "offline";
        return new BrokerSession(state, new Dictionary<string, long>
        {
            ["births"] = _node.BirthsPublished,
            ["rebirthsRequested"] = _node.RebirthsRequested,
            ["stored"] = stored,
            ["historySent"] = sent,
            ["dropped"] = dropped,
            ["foreignBirths"] = Interlocked.Read(ref _foreignBirths),
        });
    }

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

        if (topic.Type == SparkplugMessageType.NBIRTH)
        {
            ForeignBirth(message.Payload.ToArray());
        }
        else if (topic.Type == SparkplugMessageType.NCMD)
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

    /// <summary>
    /// An NBIRTH on this node's own topic: its own, come back through the subscription, or another edge node's that uses
    /// the same group and edge node id (two gateways with one configuration, under other client ids): logged once a
    /// connection, and counted.
    /// </summary>
    private void ForeignBirth(byte[] payload)
    {
        lock (_birthsGate)
        {
            if (_ownBirths.Any(b => b.AsSpan().SequenceEqual(payload)))
            {
                return;
            }

            _foreignBirths++;
            if (_foreignBirthLogged)
            {
                return;
            }

            _foreignBirthLogged = true;
        }

        string bdSeq = SparkplugPayloads.TryParse(payload)?.Metrics.FirstOrDefault(m => m.Name == SparkplugPayloads.BirthDeathSequence)?.LongValue.ToString(System.Globalization.CultureInfo.InvariantCulture) ?? "none";
        SparkplugLog.ForeignBirth(_logger, _node.GroupId, _node.EdgeNodeId, _connection.Broker, bdSeq);
    }

    private async Task RunAsync(CancellationToken cancellationToken)
    {
        IMqttClient client = _connection.Client;
        bool connected = false;
        long waitingSince = 0;
        while (!cancellationToken.IsCancellationRequested)
        {
            try
            {
                if (!client.IsConnected)
                {
                    if (connected)
                    {
                        // Lost while waiting: the same path as an error (walk, backoff, the window kept as history).
                        connected = false;
                        if (!await FailedAsync(null).ConfigureAwait(false))
                        {
                            return;
                        }

                        continue;
                    }

                    IsOnline = false;
                    _connection.Connecting();
                    await ConnectAsync(client, cancellationToken).ConfigureAwait(false);
                    _connection.Connected();
                    connected = true;
                    waitingSince = _time.GetTimestamp();
                    if (_primaryHost is null)
                    {
                        await BirthAsync(client, cancellationToken).ConfigureAwait(false);
                    }
                    else
                    {
                        SparkplugLog.WaitingForPrimaryHost(_logger, _connection.Broker, _bdSeq, _primaryHost.HostId, _primaryHost.Topic);
                    }

                    continue;
                }

                if (_primaryHost is not null)
                {
                    if (IsOnline && !_primaryHost.IsOnline)
                    {
                        connected = false;
                        if (!await EndSessionAsync($"the primary host application {_primaryHost.HostId} is offline (STATE timestamp {_primaryHost.Timestamp?.ToString(System.Globalization.CultureInfo.InvariantCulture) ?? "none"})").ConfigureAwait(false))
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
                            continue;
                        }

                        // Several servers: the specification's walk — leave a server where the host is offline (its
                        // retained STATE says so), or that has no STATE of it at all.
                        TimeSpan waited = _time.GetElapsedTime(waitingSince);
                        if (_connection.Servers.Count > 1 && (_primaryHost.Heard || waited >= _options.Timeout))
                        {
                            connected = false;
                            string why = _primaryHost.Heard
                                ? $"the primary host application {_primaryHost.HostId} is offline there"
                                : $"no STATE of the primary host application {_primaryHost.HostId} there within {_options.Timeout.TotalSeconds:0.###} s";
                            if (!await EndSessionAsync(why).ConfigureAwait(false))
                            {
                                return;
                            }

                            continue;
                        }

                        // Waiting: the node keeps taking values, and store-and-forward keeps the changes.
                        TimeSpan? limit = _connection.Servers.Count > 1 && !_primaryHost.Heard ? _options.Timeout - waited : null;
                        await WaitAsync(limit, cancellationToken).ConfigureAwait(false);
                        continue;
                    }
                }

                if (_node.RebirthRequested)
                {
                    await PublishBirthsAsync(client, cancellationToken).ConfigureAwait(false);
                    continue;
                }

                await PublishAllAsync(client, _node.TakeMessages(), cancellationToken).ConfigureAwait(false);
                if (_node.TakeHistory() is { } history)
                {
                    // One historical message, then the live ones again: live data waits for one publish at most.
                    await PublishAsync(client, history, cancellationToken).ConfigureAwait(false);
                    continue;
                }

                TimeSpan? untilConfirmation = _node.NextConfirmation is { } due ? due - _time.GetUtcNow() : null;
                await WaitAsync(untilConfirmation, cancellationToken).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
            {
                return;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                connected = false;
                if (!await FailedAsync(e).ConfigureAwait(false))
                {
                    return;
                }
            }
        }
    }

    /// <summary>Waits for something to publish, or until <paramref name="limit"/> has passed.</summary>
    private async Task WaitAsync(TimeSpan? limit, CancellationToken cancellationToken)
    {
        if (limit is not { } wait)
        {
            await _wake.Reader.ReadAsync(cancellationToken).ConfigureAwait(false);
            return;
        }

        if (wait <= TimeSpan.Zero)
        {
            return;
        }

        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        timeout.CancelAfter(wait);
        try
        {
            await _wake.Reader.ReadAsync(timeout.Token).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            // The time has come.
        }
    }

    /// <summary>After a failed attempt or a lost connection: keeps what may be lost, logs it (a warning once per outage) and waits; false when stopping.</summary>
    private async Task<bool> FailedAsync(Exception? error)
    {
        IsOnline = false;
        ConnectionEnd end = await _connection.FailedAsync(error).ConfigureAwait(false);
        if (end.WasConnected)
        {
            _node.SessionEnded(lost: true);
        }

        if (end.Warn)
        {
            SparkplugLog.Unreachable(_logger, end.Server.ToString(), end.WasConnected ? end.Problem : "unreachable", end.Reason, end.NextStep);
        }
        else
        {
            SparkplugLog.StillUnreachable(_logger, end.Server.ToString(), end.FirstFailure ? end.Problem : "still unreachable", end.Reason, end.NextStep);
        }

        return await _connection.DelayAsync(end.Delay).ConfigureAwait(false);
    }

    /// <summary>
    /// Ends the session on purpose (the primary host offline or absent): NDEATH of the session's bdSeq, a clean
    /// disconnect (so the broker drops the will), then the next server, or the backoff before the same one. False when the
    /// node is stopped meanwhile.
    /// </summary>
    private async Task<bool> EndSessionAsync(string reason)
    {
        ulong bdSeq = _bdSeq;
        ConnectionEnd end = await _connection.EndAsync((client, ct) => client.PublishAsync(NodeDeath(), ct), reason).ConfigureAwait(false);
        IsOnline = false;
        _node.SessionEnded(lost: false);
        SparkplugLog.PrimaryHostOffline(_logger, reason, bdSeq, end.Server.ToString(), end.NextStep);
        return await _connection.DelayAsync(end.Delay).ConfigureAwait(false);
    }

    /// <summary>Connects with the will of a new bdSeq and subscribes to the commands, the own births and the primary host's STATE.</summary>
    private async Task ConnectAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        // A new bdSeq for every connection: the will registered now carries it, and so does the NBIRTH that follows.
        _bdSeq = (ulong)(_connections++ % 256);
        _primaryHost?.Connecting();
        lock (_birthsGate)
        {
            _foreignBirthLogged = false;
        }

        MqttClientConnectResult result = await client.ConnectAsync(ClientOptions(_bdSeq), cancellationToken).ConfigureAwait(false);
        if (result.ResultCode != MqttClientConnectResultCode.Success)
        {
            string hint = result.ResultCode is MqttClientConnectResultCode.BadUserNameOrPassword or MqttClientConnectResultCode.NotAuthorized
                ? "; check Sparkplug:Username, Sparkplug:Password and the broker's users and ACL"
                : "";
            throw new InvalidOperationException($"the broker refused the connection: {result.ResultCode}{hint}");
        }

        MqttClientSubscribeOptionsBuilder subscribe = _factory.CreateSubscribeOptionsBuilder()
            .WithTopicFilter(f => f.WithTopic(_node.Topic(SparkplugMessageType.NCMD).ToString()).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce))
            .WithTopicFilter(f => f.WithTopic(_node.Topic(SparkplugMessageType.DCMD, "+").ToString()).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce))
            // Its own births come back; another edge node's with the same ids are how a duplicate shows.
            .WithTopicFilter(f => f.WithTopic(_node.Topic(SparkplugMessageType.NBIRTH).ToString()).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtMostOnce));
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
        int devices = await PublishBirthsAsync(client, cancellationToken).ConfigureAwait(false);
        IsOnline = true;
        SparkplugLog.Online(_logger, _connection.Broker, _node.GroupId, _node.EdgeNodeId, _bdSeq, devices);
    }

    /// <summary>Publishes the births (a session's first, or asked for by a rebirth request); how many devices were born.</summary>
    private async Task<int> PublishBirthsAsync(IMqttClient client, CancellationToken cancellationToken)
    {
        List<SparkplugMessage> births = _node.Births(_bdSeq);
        lock (_birthsGate)
        {
            _ownBirths.Enqueue(births[0].Payload);
            while (_ownBirths.Count > 4)
            {
                _ownBirths.Dequeue();
            }
        }

        await PublishAllAsync(client, births, cancellationToken).ConfigureAwait(false);
        return births.Count - 1;
    }

    private async Task PublishAllAsync(IMqttClient client, List<SparkplugMessage> messages, CancellationToken cancellationToken)
    {
        foreach (SparkplugMessage message in messages)
        {
            await PublishAsync(client, message, cancellationToken).ConfigureAwait(false);
        }
    }

    /// <summary>Publishes at QoS 0 within <see cref="MqttBrokerOptions.Timeout"/>: a socket that takes nothing is a lost connection.</summary>
    private async Task PublishAsync(IMqttClient client, SparkplugMessage message, CancellationToken cancellationToken)
    {
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        timeout.CancelAfter(_options.Timeout);
        try
        {
            await client.PublishAsync(Message(message.Topic, message.Payload, MqttQualityOfServiceLevel.AtMostOnce), timeout.Token).ConfigureAwait(false);
            _connection.Published();
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            throw new TimeoutException($"a message could not be sent within {_options.Timeout.TotalSeconds:0.###} s (Sparkplug:Timeout)");
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

    /// <summary>MQTT 3.1.1, a clean session and the NDEATH of <paramref name="bdSeq"/> as the will, for the server in use.</summary>
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
