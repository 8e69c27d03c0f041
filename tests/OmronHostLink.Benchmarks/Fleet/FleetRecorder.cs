using System.Buffers;
using System.Diagnostics;
using MQTTnet;
using MQTTnet.Formatter;
using MQTTnet.Protocol;

namespace OmronHostLink.Benchmarks.Fleet;

/// <summary>A message as the fleet's consumer received it, stamped on arrival.</summary>
internal sealed record FleetMessage(TimeSpan At, string Broker, string Topic, byte[] Payload);

/// <summary>
/// The consumer on one broker: MQTT 5, QoS 1, subscribed to the fleet's JSON topics and its Sparkplug group, recording
/// every message with when it arrived. Analysed after the run.
/// </summary>
internal sealed class FleetRecorder : IAsyncDisposable
{
    private readonly IMqttClient _client;
    private readonly List<FleetMessage> _messages = [];
    private readonly Stopwatch _clock;
    private readonly string _broker;

    private FleetRecorder(IMqttClient client, Stopwatch clock, string broker)
    {
        _client = client;
        _clock = clock;
        _broker = broker;
        _client.ApplicationMessageReceivedAsync += e =>
        {
            var message = new FleetMessage(_clock.Elapsed, _broker, e.ApplicationMessage.Topic, e.ApplicationMessage.Payload.ToArray());
            lock (_messages)
            {
                _messages.Add(message);
            }

            return Task.CompletedTask;
        };
    }

    /// <summary>Everything received so far, in order.</summary>
    public IReadOnlyList<FleetMessage> Messages
    {
        get
        {
            lock (_messages)
            {
                return _messages.ToArray();
            }
        }
    }

    public static async Task<FleetRecorder> ConnectAsync(int port, string broker, string[] filters, Stopwatch clock, CancellationToken cancellationToken)
    {
        var factory = new MqttClientFactory();
        IMqttClient client = factory.CreateMqttClient();
        var recorder = new FleetRecorder(client, clock, broker);
        MqttClientOptions options = new MqttClientOptionsBuilder()
            .WithTcpServer("127.0.0.1", port)
            .WithClientId("fleet-consumer-" + broker)
            .WithProtocolVersion(MqttProtocolVersion.V500)
            .WithCleanStart(true)
            .WithTimeout(TimeSpan.FromSeconds(30))
            .Build();
        await client.ConnectAsync(options, cancellationToken).ConfigureAwait(false);
        MqttClientSubscribeOptionsBuilder subscribe = factory.CreateSubscribeOptionsBuilder();
        foreach (string filter in filters)
        {
            subscribe = subscribe.WithTopicFilter(f => f.WithTopic(filter).WithQualityOfServiceLevel(MqttQualityOfServiceLevel.AtLeastOnce));
        }

        await client.SubscribeAsync(subscribe.Build(), cancellationToken).ConfigureAwait(false);
        return recorder;
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
            // The broker is gone (the first one is killed mid-run).
        }

        _client.Dispose();
    }
}
