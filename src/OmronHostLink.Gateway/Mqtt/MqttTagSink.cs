using System.Text;
using System.Text.Json;
using OmronHostLink.Gateway.Outputs;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Mqtt;

/// <summary>
/// The <see cref="ITagOutput"/> that feeds MQTT: keeps each tag's last value and quality, turns a change of either
/// into a retained message on the tag's topic, a change of a link's state into one on the link's status topic, and
/// queues them in the order they happened. Returns at once; the publisher loop sends the queue.
/// </summary>
internal sealed class MqttTagSink : ITagOutput
{
    private readonly object _gate = new();
    private readonly Dictionary<string, TagState> _tags = new(StringComparer.Ordinal);
    private readonly Dictionary<string, LinkState> _links = new(StringComparer.Ordinal);
    private readonly OutboundQueue _queue;
    private readonly MqttTopics _topics;

    /// <summary>Creates the sink.</summary>
    public MqttTagSink(OutboundQueue queue, MqttTopics topics)
    {
        _queue = queue;
        _topics = topics;
    }

    /// <inheritdoc/>
    public void LinkOpened(string link, HostLinkUnit client) => LinkChanged(link, LinkState.Online);

    /// <inheritdoc/>
    public void LinkChanged(string link, LinkState state, string? detail = null)
    {
        lock (_gate)
        {
            if (_links.TryGetValue(link, out LinkState last) && last == state)
            {
                return;
            }

            _links[link] = state;
            _queue.Enqueue(LinkMessage(link, state));
        }
    }

    /// <inheritdoc/>
    public void TagChanged(TagChange change)
    {
        ArgumentNullException.ThrowIfNull(change);
        string topic = _topics.Tag(change.Link, change.Unit, change.Tag);
        lock (_gate)
        {
            if (!_tags.TryGetValue(topic, out TagState? state))
            {
                state = new TagState(change.Type.Name(), change.Address);
                _tags.Add(topic, state);
            }

            object? value = change.Quality == TagQuality.Good ? change.Value : change.Value ?? state.Value;
            DateTimeOffset? time = change.Quality == TagQuality.Good ? change.Time : state.ReadTime;
            string valueJson = JsonSerializer.Serialize(value, typeof(object), MqttJson.Context);
            if (state.Published && state.Quality == change.Quality && state.ValueJson == valueJson)
            {
                return;
            }

            state.Published = true;
            state.Quality = change.Quality;
            state.Value = value;
            state.ValueJson = valueJson;
            state.ReadTime = time;
            state.Error = change.Quality == TagQuality.Good ? null : change.Error;
            _queue.Enqueue(new OutboundMessage(topic, state.Payload(), Retain: true));
        }
    }

    /// <summary>
    /// The current state of every tag and link that has no message waiting in the queue, to publish again after a
    /// (re)connection: a broker restarted without persistence has forgotten its retained messages. Topics with a
    /// message waiting are left out, so nothing older overtakes it.
    /// </summary>
    public List<OutboundMessage> Snapshot()
    {
        lock (_gate)
        {
            var messages = new List<OutboundMessage>();
            foreach ((string link, LinkState state) in _links)
            {
                OutboundMessage m = LinkMessage(link, state);
                if (!_queue.HasPending(m.Topic))
                {
                    messages.Add(m);
                }
            }

            foreach ((string topic, TagState state) in _tags)
            {
                if (!_queue.HasPending(topic))
                {
                    messages.Add(new OutboundMessage(topic, state.Payload(), Retain: true));
                }
            }

            return messages;
        }
    }

    private OutboundMessage LinkMessage(string link, LinkState state)
        => new(_topics.LinkStatus(link), Encoding.UTF8.GetBytes(state.Name()), Retain: true);

    private sealed class TagState(string type, string address)
    {
        public bool Published { get; set; }

        public TagQuality Quality { get; set; }

        public object? Value { get; set; }

        public string? ValueJson { get; set; }

        public DateTimeOffset? ReadTime { get; set; }

        public string? Error { get; set; }

        public byte[] Payload() => JsonSerializer.SerializeToUtf8Bytes(
            new TagPayload
            {
                Value = Value,
                Type = type,
                Quality = Quality.Name(),
                Time = ReadTime,
                Address = address,
                Error = Error,
            },
            MqttJson.Context.TagPayload);
    }
}
