using System.Buffers;
using System.Text.Json;
using System.Threading.Channels;
using Microsoft.Extensions.Logging;
using MQTTnet;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;
using OmronHostLink.Gateway.Writes;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// Carries out write commands one at a time: only for tags configured as writable, only with a value the tag's type
/// takes, and only through the client the link polls with (one owner of the wire): the <see cref="TagWriter"/> that
/// Sparkplug B DCMD writes go through as well. Anything else is refused and
/// logged, and nothing reaches the PLC for it. Every command gets a reply: on the MQTT 5 response topic with the
/// correlation data when the command carries them, otherwise on <c>{command topic}/result</c>.
/// </summary>
internal sealed class WriteCommandProcessor
{
    /// <summary>How many commands may wait (each is one write); more are refused at once.</summary>
    private const int Backlog = WriteBacklog.Capacity;

    private readonly Channel<WriteCommand> _commands = Channel.CreateBounded<WriteCommand>(new BoundedChannelOptions(Backlog) { SingleReader = true });
    private readonly MqttTopics _topics;
    private readonly TagCatalog _catalog;
    private readonly TagWriter _writer;
    private readonly OutboundQueue _queue;
    private readonly MqttMetrics _metrics;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly bool _enabled;
    private readonly string[] _replyPrefixes;

    /// <summary>A command's JSON as written: a property given twice is an error, not "the last one wins".</summary>
    private static readonly JsonDocumentOptions StrictJson = new() { AllowDuplicateProperties = false };

    /// <summary>Creates the processor.</summary>
    public WriteCommandProcessor(MqttOptions options, MqttTopics topics, TagCatalog catalog, OpenLinks links, OutboundQueue queue, MqttMetrics metrics, ILogger<WriteCommandProcessor> logger, TimeProvider timeProvider)
    {
        ArgumentNullException.ThrowIfNull(options);
        _enabled = options.Writes.Enabled;
        _replyPrefixes = options.Writes.ReplyPrefixes.ToArray();
        _topics = topics;
        _catalog = catalog;
        _writer = new TagWriter(links);
        _queue = queue;
        _metrics = metrics;
        _logger = logger;
        _time = timeProvider;
    }

    /// <summary>Takes a command from the MQTT client's receive path; never blocks it.</summary>
    public void Accept(MqttApplicationMessage message)
    {
        ArgumentNullException.ThrowIfNull(message);
        var command = new WriteCommand(message.Topic, message.Payload.ToArray(), message.ResponseTopic, message.CorrelationData, message.Retain);
        if (!_commands.Writer.TryWrite(command))
        {
            Refuse(command, TagTopic(command), $"{Backlog} write commands are already waiting; send it again later.");
        }
    }

    /// <summary>Carries out commands in the order they came until <paramref name="cancellationToken"/> is cancelled.</summary>
    public async Task RunAsync(CancellationToken cancellationToken)
    {
        try
        {
            await foreach (WriteCommand command in _commands.Reader.ReadAllAsync(cancellationToken).ConfigureAwait(false))
            {
                await ProcessAsync(command, cancellationToken).ConfigureAwait(false);
            }
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            // Stopping.
        }
    }

    /// <summary>
    /// Carries out one command as <see cref="ExecuteAsync"/> does, and answers it even when the gateway fails on it:
    /// a bug must not end the loop (every later command would go unanswered). The reply then says what the sender can
    /// act on, naming the command's tag; what went wrong inside is for the log.
    /// </summary>
    /// <returns>The reply; null for a command ignored without one.</returns>
    public async Task<WriteResultPayload?> ProcessAsync(WriteCommand command, CancellationToken cancellationToken)
    {
        try
        {
            return await ExecuteAsync(command, cancellationToken).ConfigureAwait(false);
        }
        catch (Exception e) when (e is not OperationCanceledException && e is not OutOfMemoryException)
        {
            MqttLog.WriteCrashed(_logger, e, command.Topic);
            return Reply(command, new WriteResultPayload
            {
                Status = TagWriteStatus.Failed.Name(),
                Tag = TagTopic(command),
                Error = $"the gateway failed on the command (its log has the details, event {MqttLog.Events.WriteCrashed}); read the value back to know whether it reached the PLC.",
                Time = _time.GetUtcNow(),
            });
        }
    }

    /// <summary>Checks and carries out one command, and queues its reply.</summary>
    /// <returns>The reply; null for a command ignored without one (clearing a retained command).</returns>
    public async Task<WriteResultPayload?> ExecuteAsync(WriteCommand command, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(command);
        if (command.Retained && command.Payload.Length == 0)
        {
            // Someone clears a retained command (publish -r with no payload): nothing to do and nobody to answer.
            MqttLog.RetainedCommandCleared(_logger, command.Topic);
            return null;
        }

        if (!_topics.TryParseCommand(command.Topic, out string link, out int unit, out string name))
        {
            return Refuse(command, command.Topic, $"{command.Topic} is not a command topic ({_topics.Prefix}/{{link}}/{{unit}}/{{tag}}/set).");
        }

        string tagTopic = _topics.Tag(link, unit, name);
        if (!IsAllowedReplyTopic(command))
        {
            return Refuse(command, tagTopic, $"the response topic '{Shorten(command.ResponseTopic!)}' is neither this command's result topic nor under a reply prefix (Mqtt:Writes:ReplyPrefixes); the reply goes to {MqttTopics.ResultTopic(command.Topic)}.");
        }

        if (!_enabled)
        {
            return Refuse(command, tagTopic, "writes are disabled (Mqtt:Writes:Enabled is false).");
        }

        if (command.Retained)
        {
            return Refuse(command, tagTopic, "the command was published with the retain flag; a retained command would run again for every new subscriber, so publish write commands without it.");
        }

        TagDefinition? tag = _catalog.Find(link, unit, name);
        if (tag is null)
        {
            return Refuse(command, tagTopic, $"this gateway has no tag {name} on unit {unit} of link {link}.");
        }

        if (!tag.Writable)
        {
            return Refuse(command, tagTopic, $"{link}/{unit}/{name} is not writable; only tags with Writable: true (HostLink:Links:{link}:Groups:{name}:Writable) take writes.");
        }

        JsonElement value;
        try
        {
            using JsonDocument document = JsonDocument.Parse(command.Payload, StrictJson);
            JsonElement root = document.RootElement;
            if (root.ValueKind == JsonValueKind.Object)
            {
                foreach (JsonProperty property in root.EnumerateObject())
                {
                    if (property.Name != "value")
                    {
                        return Refuse(command, tagTopic, $"the payload's object holds \"{Shorten(property.Name)}\"; it takes \"value\" only: {{\"value\": 1234}}.");
                    }
                }

                if (!root.TryGetProperty("value", out JsonElement inner))
                {
                    return Refuse(command, tagTopic, "the payload is a JSON object without \"value\"; send the value bare (1234) or as {\"value\": 1234}.");
                }

                root = inner;
            }

            value = root.Clone();
        }
        catch (JsonException e)
        {
            return Refuse(command, tagTopic, $"the payload is not JSON ({e.Message}); send the value bare (1234, \"TEXT\", true) or as {{\"value\": 1234}}.");
        }

        string valueText = Shorten(value.GetRawText());
        TagWriteOutcome outcome = await _writer.WriteAsync(tag, value, element: null, cancellationToken).ConfigureAwait(false);
        if (outcome.Status == TagWriteStatus.Refused)
        {
            return Refuse(command, tagTopic, outcome.Error!);
        }

        if (outcome.IsDone)
        {
            MqttLog.WriteDone(_logger, tagTopic, tag.Address.ToString(), valueText);
            return Reply(command, new WriteResultPayload { Status = TagWriteStatus.Done.Name(), Tag = tagTopic, Time = _time.GetUtcNow() });
        }

        MqttLog.WriteFailed(_logger, tagTopic, tag.Address.ToString(), valueText, outcome.Error!);
        return Reply(command, new WriteResultPayload { Status = TagWriteStatus.Failed.Name(), Tag = tagTopic, Error = outcome.Error, EndCode = outcome.EndCode, Time = _time.GetUtcNow() });
    }

    private WriteResultPayload Refuse(WriteCommand command, string tagTopic, string reason)
    {
        MqttLog.WriteRefused(_logger, command.Topic, reason);
        return Reply(command, new WriteResultPayload { Status = TagWriteStatus.Refused.Name(), Tag = tagTopic, Error = reason, Time = _time.GetUtcNow() });
    }

    private WriteResultPayload Reply(WriteCommand command, WriteResultPayload result)
    {
        _metrics.Write(result.Status);
        bool useResponseTopic = !string.IsNullOrEmpty(command.ResponseTopic) && IsAllowedReplyTopic(command);
        string topic = useResponseTopic ? command.ResponseTopic! : MqttTopics.ResultTopic(command.Topic);
        byte[] payload = JsonSerializer.SerializeToUtf8Bytes(result, MqttJson.Context.WriteResultPayload);
        _queue.Enqueue(new OutboundMessage(topic, payload, Retain: false, useResponseTopic ? command.CorrelationData : null));
        return result;
    }

    /// <summary>
    /// No response topic, the command's own result topic, or a topic under a configured reply prefix: a reply can never
    /// land on a value, status or command topic, nor anywhere else the gateway's credentials may publish.
    /// </summary>
    private bool IsAllowedReplyTopic(WriteCommand command)
    {
        string? topic = command.ResponseTopic;
        if (string.IsNullOrEmpty(topic))
        {
            return true;
        }

        if (!MqttTopics.IsPublishable(topic))
        {
            return false;
        }

        return topic == MqttTopics.ResultTopic(command.Topic)
            || _replyPrefixes.Any(p => topic.StartsWith(p + "/", StringComparison.Ordinal) && topic.Length > p.Length + 1);
    }

    /// <summary>The value topic of the tag a command is for; the command's own topic when it names none.</summary>
    private string TagTopic(WriteCommand command)
        => _topics.TryParseCommand(command.Topic, out string link, out int unit, out string tag) ? _topics.Tag(link, unit, tag) : command.Topic;

    private static string Shorten(string text) => text.Length > 60 ? text.Substring(0, 60) + "…" : text;
}
