using System.Buffers;
using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// A consumer on the far side of the broker: subscribed to <c>{prefix}/#</c> with QoS 1 (MQTT 5), it stamps each tag
/// message with the time it arrived and hands the value to the <see cref="ChangeLedger"/>. Tag topics are
/// <c>{prefix}/{link}/{unit}/{tag}</c>; status topics are counted only.
/// </summary>
internal sealed class ChangeSubscriber : IAsyncDisposable
{
    private static readonly byte[] ValueName = "value"u8.ToArray();
    private static readonly byte[] QualityName = "quality"u8.ToArray();
    private static readonly byte[] TimeName = "time"u8.ToArray();
    private static readonly byte[] Good = "good"u8.ToArray();

    private readonly IMqttClient _client;
    private readonly ChangeLedger _ledger;
    private readonly Dictionary<string, int> _tagByTopic;
    private long _messages;
    private long _unparsed;

    private ChangeSubscriber(IMqttClient client, ChangeLedger ledger, Dictionary<string, int> tagByTopic)
    {
        _client = client;
        _ledger = ledger;
        _tagByTopic = tagByTopic;
        _client.ApplicationMessageReceivedAsync += e =>
        {
            OnMessage(e.ApplicationMessage);
            return Task.CompletedTask;
        };
    }

    /// <summary>Every message received, status topics included.</summary>
    public long Messages => Interlocked.Read(ref _messages);

    /// <summary>Tag messages whose payload could not be read (must be 0).</summary>
    public long Unparsed => Interlocked.Read(ref _unparsed);

    public static async Task<ChangeSubscriber> ConnectAsync(int port, string prefix, ChangeLedger ledger, Dictionary<string, int> tagByTopic, CancellationToken cancellationToken)
    {
        var factory = new MqttClientFactory();
        IMqttClient client = factory.CreateMqttClient();
        var subscriber = new ChangeSubscriber(client, ledger, tagByTopic);
        MqttClientOptions options = new MqttClientOptionsBuilder()
            .WithTcpServer("127.0.0.1", port)
            .WithClientId("scale-subscriber")
            .WithProtocolVersion(MqttProtocolVersion.V500)
            .WithCleanStart(true)
            .WithTimeout(TimeSpan.FromSeconds(10))
            .Build();
        MqttClientConnectResult connected = await client.ConnectAsync(options, cancellationToken).ConfigureAwait(false);
        if (connected.ResultCode != MqttClientConnectResultCode.Success)
        {
            client.Dispose();
            throw new InvalidOperationException($"The subscriber could not connect: {connected.ResultCode} {connected.ReasonString}");
        }

        MqttClientSubscribeOptions subscribe = factory.CreateSubscribeOptionsBuilder()
            .WithTopicFilter(f => f.WithTopic(prefix + "/#").WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce))
            .Build();
        await client.SubscribeAsync(subscribe, cancellationToken).ConfigureAwait(false);
        return subscriber;
    }

    public async ValueTask DisposeAsync()
    {
        try
        {
            if (_client.IsConnected)
            {
                using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(5));
                await _client.DisconnectAsync(new MqttClientDisconnectOptions(), timeout.Token).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // The broker may already be gone.
        }

        _client.Dispose();
    }

    private void OnMessage(MqttApplicationMessage message)
    {
        long arrived = Stopwatch.GetTimestamp();
        DateTimeOffset arrivedUtc = DateTimeOffset.UtcNow;
        Interlocked.Increment(ref _messages);
        if (!_tagByTopic.TryGetValue(message.Topic, out int tag))
        {
            return;
        }

        if (!TryRead(message.Payload, out int value, out bool good, out DateTimeOffset? readTime))
        {
            Interlocked.Increment(ref _unparsed);
            return;
        }

        double readToReceive = readTime is { } t ? (arrivedUtc - t).TotalMilliseconds : double.NaN;
        _ledger.Received(tag, value, good, arrived, readToReceive);
    }

    /// <summary>Reads <c>value</c> (a number), <c>quality</c> and <c>time</c> of a tag payload.</summary>
    private static bool TryRead(ReadOnlySequence<byte> payload, out int value, out bool good, out DateTimeOffset? time)
    {
        value = -1;
        good = false;
        time = null;
        var reader = new Utf8JsonReader(payload);
        try
        {
            if (!reader.Read() || reader.TokenType != JsonTokenType.StartObject)
            {
                return false;
            }

            while (reader.Read() && reader.TokenType == JsonTokenType.PropertyName)
            {
                if (reader.ValueTextEquals(ValueName))
                {
                    reader.Read();
                    if (reader.TokenType == JsonTokenType.Number)
                    {
                        value = reader.GetInt32();
                    }
                }
                else if (reader.ValueTextEquals(QualityName))
                {
                    reader.Read();
                    good = reader.ValueTextEquals(Good);
                }
                else if (reader.ValueTextEquals(TimeName))
                {
                    reader.Read();
                    if (reader.TokenType == JsonTokenType.String
                        && DateTimeOffset.TryParse(reader.GetString(), CultureInfo.InvariantCulture, DateTimeStyles.AssumeUniversal, out DateTimeOffset parsed))
                    {
                        time = parsed;
                    }
                }
                else
                {
                    reader.Read();
                    reader.TrySkip();
                }
            }
        }
        catch (JsonException)
        {
            return false;
        }

        return value >= 0 || !good;
    }
}
