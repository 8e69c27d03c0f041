using System.Text.Json;
using Microsoft.Extensions.Logging;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The JSON output's outbound queue: kept in <see cref="MqttOptions.StateDirectory"/> under the client id's name,
/// bounded by <c>Mqtt:QueueCapacity</c> (and <c>Mqtt:DurableQueue</c>), announcing what a previous run may have lost
/// on <see cref="MqttTopics.WorkerLost"/>.
/// </summary>
internal static class MqttOutboundQueue
{
    /// <summary>The state directory in effect for <paramref name="options"/>.</summary>
    public static string StateDirectoryIn(this MqttOptions options, string contentRoot)
        => OutboundQueueStore.StateDirectory(options.StateDirectory, contentRoot);

    /// <summary>The durable queue's database for <paramref name="options"/>.</summary>
    public static string JournalPath(this MqttOptions options, string contentRoot)
        => OutboundQueueStore.JournalPath(options.StateDirectoryIn(contentRoot), options.ClientIdOrDefault);

    /// <summary>Opens the queue's files for <paramref name="options"/>.</summary>
    public static OutboundQueueStore OpenStore(MqttOptions options, string contentRoot, ILogger logger)
        => new(options.StateDirectoryIn(contentRoot), options.ClientIdOrDefault, options.DurableQueue, logger);

    /// <summary>The queue of <paramref name="options"/>, with the previous run's messages and its loss announced on <paramref name="topics"/>.</summary>
    public static OutboundQueue CreateQueue(this OutboundQueueStore store, MqttOptions options, MqttTopics topics, TimeProvider timeProvider)
        => store.CreateQueue(options.QueueCapacity, timeProvider, lost => new OutboundMessage(
            topics.WorkerLost,
            JsonSerializer.SerializeToUtf8Bytes(new LostMessagesPayload { Lost = lost, Time = timeProvider.GetUtcNow() }, MqttJson.Context.LostMessagesPayload),
            Retain: false));
}
