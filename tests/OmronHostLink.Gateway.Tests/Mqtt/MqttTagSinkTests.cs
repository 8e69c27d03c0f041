using System.Text;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Tests.Mqtt;

public sealed class MqttTagSinkTests
{
    private static readonly DateTimeOffset T0 = new(2025, 1, 31, 8, 0, 0, 125, TimeSpan.Zero);
    private readonly OutboundQueue _queue = new(100);
    private readonly MqttTagSink _sink;

    public MqttTagSinkTests() => _sink = new MqttTagSink(_queue, new MqttTopics("plant/a", "worker-1"));

    private static TagChange Good(object value, DateTimeOffset time) => new("line1", 3, "levels", "D100", PlcValueType.Int16, value, TagQuality.Good, time);

    private List<(string Topic, string Payload, bool Retain)> Drain()
    {
        var messages = new List<(string, string, bool)>();
        while (_queue.TryPeek(out OutboundMessage? m))
        {
            messages.Add((m.Topic, Encoding.UTF8.GetString(m.Payload), m.Retain));
            _queue.Remove(m);
        }

        return messages;
    }

    [Fact]
    public void A_value_is_published_retained_as_json_once_and_again_only_when_it_changes()
    {
        _sink.TagChanged(Good(new short[] { 120, -340 }, T0));
        _sink.TagChanged(Good(new short[] { 120, -340 }, T0.AddSeconds(1)));
        _sink.TagChanged(Good(new short[] { 121, -340 }, T0.AddSeconds(2)));

        Drain().Should().Equal(
            ("plant/a/line1/3/levels", """{"value":[120,-340],"type":"int16","quality":"good","time":"2025-01-31T08:00:00.125Z","address":"D100"}""", true),
            ("plant/a/line1/3/levels", """{"value":[121,-340],"type":"int16","quality":"good","time":"2025-01-31T08:00:02.125Z","address":"D100"}""", true));
    }

    [Fact]
    public void A_failure_keeps_the_last_value_and_its_read_time_and_says_why()
    {
        _sink.TagChanged(Good((short)7, T0));
        _sink.TagChanged(new TagChange("line1", 3, "levels", "D100", PlcValueType.Int16, null, TagQuality.CommError, T0.AddSeconds(5), "No answer within 421 ms."));
        _sink.TagChanged(new TagChange("line1", 3, "levels", "D100", PlcValueType.Int16, null, TagQuality.CommError, T0.AddSeconds(6), "No answer within 421 ms."));
        _sink.TagChanged(new TagChange("line1", 3, "levels", "D100", PlcValueType.Int16, null, TagQuality.Stale, T0.AddSeconds(7), "end code 04"));
        _sink.TagChanged(Good((short)7, T0.AddSeconds(8)));

        Drain().Select(m => m.Payload).Should().Equal(
            """{"value":7,"type":"int16","quality":"good","time":"2025-01-31T08:00:00.125Z","address":"D100"}""",
            """{"value":7,"type":"int16","quality":"comm-error","time":"2025-01-31T08:00:00.125Z","address":"D100","error":"No answer within 421 ms."}""",
            """{"value":7,"type":"int16","quality":"stale","time":"2025-01-31T08:00:00.125Z","address":"D100","error":"end code 04"}""",
            """{"value":7,"type":"int16","quality":"good","time":"2025-01-31T08:00:08.125Z","address":"D100"}""");
    }

    [Fact]
    public void A_tag_never_read_reports_comm_error_with_null_value_and_time()
    {
        _sink.TagChanged(new TagChange("line1", 0, "t", "T5", PlcValueType.Bit, null, TagQuality.CommError, T0, "gone"));
        Drain().Single().Payload.Should().Be("""{"value":null,"type":"bit","quality":"comm-error","time":null,"address":"T5","error":"gone"}""");
    }

    [Fact]
    public void A_real_that_is_not_a_number_is_written_as_a_string()
    {
        _sink.TagChanged(new TagChange("line1", 0, "f", "D200", PlcValueType.Float, new[] { float.NaN, 1.5f, float.PositiveInfinity }, TagQuality.Good, T0));
        Drain().Single().Payload.Should().StartWith("""{"value":["NaN",1.5,"Infinity"],"type":"float",""");
    }

    [Fact]
    public void Link_states_go_to_the_link_status_topic_as_plain_text_on_change()
    {
        _sink.LinkOpened("line1", HostLinkClient.ForStream(new MemoryStream()));
        _sink.LinkChanged("line1", LinkState.Online);
        _sink.LinkChanged("line1", LinkState.CommError, "timeout");
        _sink.LinkChanged("line1", LinkState.Online);
        _sink.LinkChanged("line1", LinkState.Offline);

        Drain().Should().Equal(
            ("plant/a/line1/status", "online", true),
            ("plant/a/line1/status", "comm-error", true),
            ("plant/a/line1/status", "online", true),
            ("plant/a/line1/status", "offline", true));
    }

    [Fact]
    public void An_offline_link_has_no_client_for_writes()
    {
        var links = new OpenLinks();
        links.LinkOpened("line1", HostLinkClient.ForStream(new MemoryStream()));
        links.ClientOf("line1").Should().NotBeNull();
        links.LinkChanged("line1", LinkState.Offline);
        links.ClientOf("line1").Should().BeNull("an offline link takes no writes");
    }

    [Fact]
    public void The_snapshot_after_a_reconnection_leaves_out_topics_with_a_message_waiting()
    {
        _sink.TagChanged(Good((short)1, T0));
        _sink.TagChanged(new TagChange("line1", 3, "other", "D200", PlcValueType.Int16, (short)5, TagQuality.Good, T0));
        _sink.LinkChanged("line1", LinkState.Online);
        Drain();
        _sink.TagChanged(Good((short)2, T0.AddSeconds(1))); // waits in the queue

        List<OutboundMessage> snapshot = _sink.Snapshot();

        snapshot.Select(m => m.Topic).Should().BeEquivalentTo("plant/a/line1/status", "plant/a/line1/3/other");
        snapshot.Should().OnlyContain(m => m.Retain);
        Encoding.UTF8.GetString(snapshot.Single(m => m.Topic == "plant/a/line1/3/other").Payload).Should().Contain("\"value\":5");
    }
}
