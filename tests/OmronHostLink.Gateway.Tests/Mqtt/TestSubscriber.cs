using System.Buffers;
using System.Diagnostics;
using System.Text;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>A message as a test subscriber received it (<see cref="Bytes"/>: the payload as sent, for binary payloads).</summary>
public sealed record ReceivedMessage(string Topic, string Payload, bool Retain, string? ResponseTopic, byte[]? CorrelationData, byte[]? Bytes = null, bool Duplicate = false);

/// <summary>
/// An MQTTnet client on the test's side of the broker: records what arrives on its subscriptions and waits for
/// conditions on it (woken by each message, with a generous timeout). With a persistent session it reconnects by
/// itself after the broker restarts, and the broker keeps what arrived meanwhile for it.
/// </summary>
public sealed class TestSubscriber : IAsyncDisposable
{
    private static readonly TimeSpan DefaultPatience = TimeSpan.FromSeconds(20);
    private readonly List<ReceivedMessage> _messages = new();
    private readonly MqttClientFactory _factory = new();
    private readonly IMqttClient _client;
    private readonly MqttClientOptions _options;
    private readonly string[] _filters;
    private readonly CancellationTokenSource _closing = new();
    private TaskCompletionSource _changed = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private Task? _reconnecting;

    private TestSubscriber(MqttClientOptions options, string[] filters)
    {
        _client = _factory.CreateMqttClient();
        _options = options;
        _filters = filters;
        _client.ApplicationMessageReceivedAsync += e =>
        {
            MqttApplicationMessage m = e.ApplicationMessage;
            byte[] bytes = m.Payload.ToArray();
            var received = new ReceivedMessage(m.Topic, Encoding.UTF8.GetString(bytes), m.Retain, m.ResponseTopic, m.CorrelationData, bytes, m.Dup);
            lock (_messages)
            {
                _messages.Add(received);
            }

            Signal();
            return Task.CompletedTask;
        };
        _client.DisconnectedAsync += e =>
        {
            if (!_closing.IsCancellationRequested && e.ClientWasConnected)
            {
                _reconnecting = Task.Run(ReconnectAsync);
            }

            Signal();
            return Task.CompletedTask;
        };
    }

    /// <summary>Everything received so far, in order.</summary>
    public IReadOnlyList<ReceivedMessage> Messages
    {
        get
        {
            lock (_messages)
            {
                return _messages.ToArray();
            }
        }
    }

    /// <summary>Whether the client is connected.</summary>
    public bool IsConnected => _client.IsConnected;

    /// <summary>Connects to <paramref name="broker"/> and subscribes to <paramref name="filters"/> (QoS 1).</summary>
    /// <param name="broker">The broker.</param>
    /// <param name="filters">Topic filters; <c>#</c> when none.</param>
    /// <param name="clientId">A fixed client id (needed for a persistent session).</param>
    /// <param name="persistentSession">Keep the session (and the messages queued for it) across disconnections and broker restarts.</param>
    /// <param name="username">User name, for a broker with a password file.</param>
    /// <param name="password">Password.</param>
    public static async Task<TestSubscriber> ConnectAsync(MosquittoBroker broker, string[]? filters = null, string? clientId = null, bool persistentSession = false, string? username = null, string? password = null)
    {
        MqttClientOptionsBuilder builder = new MqttClientOptionsBuilder()
            .WithTcpServer("127.0.0.1", broker.Port)
            .WithClientId(clientId ?? "test-" + Guid.NewGuid().ToString("N"))
            .WithProtocolVersion(MqttProtocolVersion.V500)
            .WithTimeout(TimeSpan.FromSeconds(10))
            .WithCleanStart(!persistentSession);
        if (persistentSession)
        {
            builder = builder.WithSessionExpiryInterval(3600);
        }

        if (username is not null)
        {
            builder = builder.WithCredentials(username, password);
        }

        if (broker.Settings.Tls is not null)
        {
            // The subscriber's own trust is not what is tested.
            // A broker that requires client certificates gets one of its own CA.
            System.Security.Cryptography.X509Certificates.X509Certificate2? certificate = broker.Settings.RequireCertificate ? broker.Settings.Tls.CreateClient("test-subscriber") : null;
            builder = builder.WithTlsOptions(o =>
            {
                o.UseTls().WithTargetHost("127.0.0.1").WithCertificateValidationHandler(_ => true);
                if (certificate is not null)
                {
                    o.WithClientCertificates([certificate]);
                }
            });
        }

        var subscriber = new TestSubscriber(builder.Build(), filters ?? ["#"]);
        await subscriber.ConnectAndSubscribeAsync(CancellationToken.None);
        return subscriber;
    }

    /// <summary>Publishes a message (QoS 1, not retained unless asked).</summary>
    public Task<MqttClientPublishResult> PublishAsync(string topic, string payload, string? responseTopic = null, byte[]? correlationData = null, bool retain = false)
    {
        MqttApplicationMessageBuilder builder = new MqttApplicationMessageBuilder()
            .WithTopic(topic)
            .WithPayload(payload)
            .WithRetainFlag(retain)
            .WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce);
        if (responseTopic is not null)
        {
            builder = builder.WithResponseTopic(responseTopic);
        }

        if (correlationData is not null)
        {
            builder = builder.WithCorrelationData(correlationData);
        }

        return _client.PublishAsync(builder.Build());
    }

    /// <summary>Publishes a binary payload (QoS 1, not retained).</summary>
    public Task<MqttClientPublishResult> PublishAsync(string topic, byte[] payload)
        => _client.PublishAsync(new MqttApplicationMessageBuilder().WithTopic(topic).WithPayload(payload).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce).Build());

    /// <summary>The payloads received on <paramref name="topic"/>, in order.</summary>
    public IReadOnlyList<string> PayloadsOn(string topic) => Messages.Where(m => m.Topic == topic).Select(m => m.Payload).ToArray();

    /// <summary>Waits until <paramref name="condition"/> holds for the messages received, re-checked on every message.</summary>
    /// <exception cref="Xunit.Sdk.XunitException">It did not hold within the patience (20 s by default).</exception>
    public async Task WaitUntilAsync(Func<IReadOnlyList<ReceivedMessage>, bool> condition, string what, TimeSpan? patience = null)
    {
        TimeSpan limit = patience ?? DefaultPatience;
        var clock = Stopwatch.StartNew();
        while (true)
        {
            Task changed;
            lock (_messages)
            {
                changed = _changed.Task;
            }

            if (condition(Messages))
            {
                return;
            }

            TimeSpan left = limit - clock.Elapsed;
            if (left <= TimeSpan.Zero)
            {
                throw new Xunit.Sdk.XunitException($"Timed out after {limit.TotalSeconds} s waiting until {what}. Received:{Environment.NewLine}{Dump()}");
            }

            // The timeout is a safety net; each message wakes the check.
            await Task.WhenAny(changed, Task.Delay(left < TimeSpan.FromSeconds(1) ? left : TimeSpan.FromSeconds(1)));
        }
    }

    /// <summary>Waits for the first message on <paramref name="topic"/> that satisfies <paramref name="match"/>.</summary>
    public async Task<ReceivedMessage> WaitForAsync(string topic, Func<ReceivedMessage, bool>? match = null, TimeSpan? patience = null)
    {
        await WaitUntilAsync(ms => ms.Any(m => m.Topic == topic && (match?.Invoke(m) ?? true)), $"a message on {topic}", patience);
        return Messages.First(m => m.Topic == topic && (match?.Invoke(m) ?? true));
    }

    /// <summary>Everything received, one line each (for failure messages).</summary>
    public string Dump() => string.Join(Environment.NewLine, Messages.Select(m => $"  {m.Topic}{(m.Retain ? " (retained)" : "")}{(m.Duplicate ? " (redelivered)" : "")}: {m.Payload}"));

    /// <inheritdoc/>
    public async ValueTask DisposeAsync()
    {
        await _closing.CancelAsync();
        try
        {
            if (_client.IsConnected)
            {
                await _client.DisconnectAsync(new MqttClientDisconnectOptions());
            }
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
        }

        if (_reconnecting is not null)
        {
            await _reconnecting.ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
        }

        _client.Dispose();
        _closing.Dispose();
    }

    private async Task ConnectAndSubscribeAsync(CancellationToken cancellationToken)
    {
        MqttClientConnectResult result = await _client.ConnectAsync(_options, cancellationToken);
        if (result.ResultCode != MqttClientConnectResultCode.Success)
        {
            throw new InvalidOperationException($"The test subscriber could not connect: {result.ResultCode} {result.ReasonString}");
        }

        if (result.IsSessionPresent)
        {
            return;
        }

        MqttClientSubscribeOptionsBuilder subscribe = _factory.CreateSubscribeOptionsBuilder();
        foreach (string filter in _filters)
        {
            subscribe = subscribe.WithTopicFilter(f => f.WithTopic(filter).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce));
        }

        await _client.SubscribeAsync(subscribe.Build(), cancellationToken);
    }

    private async Task ReconnectAsync()
    {
        while (!_closing.IsCancellationRequested)
        {
            try
            {
                await ConnectAndSubscribeAsync(_closing.Token);
                Signal();
                return;
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                try
                {
                    await Task.Delay(100, _closing.Token);
                }
                catch (OperationCanceledException)
                {
                    return;
                }
            }
        }
    }

    private void Signal()
    {
        TaskCompletionSource done;
        lock (_messages)
        {
            done = _changed;
            _changed = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        }

        done.TrySetResult();
    }
}
