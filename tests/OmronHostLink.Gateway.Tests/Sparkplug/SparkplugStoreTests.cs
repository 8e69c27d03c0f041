using Microsoft.Extensions.Logging.Abstractions;
using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Sparkplug;
using OmronHostLink.Gateway.Sparkplug.Wire;
using OmronHostLink.Gateway.Tests.Mqtt;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>
/// Store-and-forward in the edge node, driven by a fake clock: what is kept outside a session, what is published live,
/// what comes back as history after the births, and what a lost connection keeps again. Decoded with the gateway's own
/// payload classes; the end-to-end tests decode with Eclipse Tahu.
/// </summary>
public sealed class SparkplugStoreTests : IDisposable
{
    private static readonly DateTimeOffset T0 = new(2025, 3, 1, 8, 0, 0, TimeSpan.Zero);
    private readonly FakeTimeProvider _time = new(T0);
    private readonly List<SparkplugHistory> _histories = [];

    public void Dispose()
    {
        foreach (SparkplugHistory history in _histories)
        {
            history.Dispose();
        }
    }

    [Fact]
    public void Changes_made_outside_a_session_follow_the_births_as_history_oldest_first_without_the_values_the_births_carry()
    {
        SparkplugNode node = Node();
        Read(node, "a", 1);
        Read(node, "b", 10);
        Read(node, "a", 2);
        Read(node, "a", 3);

        List<SparkplugMessage> births = node.Births(0);
        births.Select(m => m.Topic.Type).Should().Equal(SparkplugMessageType.NBIRTH, SparkplugMessageType.DBIRTH);
        Payload birth = Decode(births[1]);
        birth.Metrics.Select(m => (m.Name, (short)m.IntValue)).Should().Equal(("a", 3), ("b", 10));

        SparkplugMessage history = node.TakeHistory()!;
        history.Topic.Type.Should().Be(SparkplugMessageType.DDATA);
        Payload data = Decode(history);
        data.Seq.Should().Be(2, "history is numbered like any message of the node");
        // a=1, a=2 before the birth; a=3 and b=10 are what the birth carries.
        data.Metrics.Select(m => (m.Alias, (short)m.IntValue, m.IsHistorical, m.HasName)).Should().Equal((1UL, (short)1, true, false), (1UL, (short)2, true, false));
        data.Metrics.Select(m => m.Timestamp).Should().BeInAscendingOrder().And.OnlyHaveUniqueItems("each change keeps the time the PLC was read");
        node.TakeHistory().Should().BeNull("nothing else is kept");
    }

    [Fact]
    public void In_a_session_every_change_is_a_data_message_in_the_order_read_a_metric_twice_with_its_two_times()
    {
        SparkplugNode node = Node();
        Read(node, "a", 1);
        Read(node, "b", 10);
        node.Births(0);
        node.TakeHistory().Should().BeNull();

        Read(node, "a", 2);
        Read(node, "a", 3);
        Read(node, "b", 11);
        List<SparkplugMessage> live = node.TakeMessages();

        live.Should().ContainSingle();
        Payload data = Decode(live[0]);
        data.Metrics.Select(m => (m.Alias, (short)m.IntValue, m.IsHistorical)).Should().Equal((1UL, (short)2, false), (1UL, (short)3, false), (2UL, (short)11, false));
        data.Metrics.Where(m => m.Alias == 1).Select(m => m.Timestamp).Should().BeInAscendingOrder().And.OnlyHaveUniqueItems();
    }

    [Fact]
    public void A_lost_connection_sends_unconfirmed_history_again_and_keeps_the_changes_published_within_the_window()
    {
        SparkplugNode node = Node(keepAlive: TimeSpan.FromSeconds(10));
        Read(node, "a", 1);
        Read(node, "b", 10);
        Read(node, "a", 2);
        node.Births(0);
        Decode(node.TakeHistory()!).Metrics.Select(m => (short)m.IntValue).Should().Equal(1);

        // Lost before 1.5 x keep-alive passed: that history may not have arrived.
        node.SessionEnded(lost: true);
        node.Births(1);
        Decode(node.TakeHistory()!).Metrics.Select(m => (short)m.IntValue).Should().Equal([1], "sent again");
        _time.Advance(TimeSpan.FromSeconds(16));
        node.TakeHistory().Should().BeNull();
        node.Store.Stored.Should().Be(0);

        // Live: a=3 published long before the loss (safe), a=4 within the window, a=5 not published at all.
        Read(node, "a", 3);
        node.TakeMessages().Should().ContainSingle();
        _time.Advance(TimeSpan.FromSeconds(20));
        Read(node, "a", 4);
        node.TakeMessages().Should().ContainSingle();
        Read(node, "a", 5);
        node.SessionEnded(lost: true);

        Payload birth = Decode(node.Births(2)[1]);
        birth.Metrics.Single(m => m.Name == "a").IntValue.Should().Be(5);
        Decode(node.TakeHistory()!).Metrics.Select(m => (short)m.IntValue).Should().Equal([4], "a=4 may have died with the connection; a=5 is in the birth");
    }

    [Fact]
    public void History_published_leaves_the_store_once_the_window_has_passed_and_a_session_ended_on_purpose_keeps_nothing_again()
    {
        SparkplugNode node = Node(keepAlive: TimeSpan.FromSeconds(10));
        Read(node, "a", 1);
        Read(node, "b", 10);
        Read(node, "a", 2);
        node.Births(0);
        node.TakeHistory().Should().NotBeNull();
        node.Store.Stored.Should().Be(3, "published, not yet confirmed");

        _time.Advance(TimeSpan.FromSeconds(16));
        node.TakeHistory().Should().BeNull();
        node.Store.Stored.Should().Be(0, "confirmed once 1.5 x keep-alive passed with the connection up");

        Read(node, "a", 5);
        node.TakeMessages().Should().ContainSingle();
        node.SessionEnded(lost: false);
        node.Births(1);
        node.TakeHistory().Should().BeNull("a session ended on purpose takes what was published as received");
    }

    [Fact]
    public void Beyond_its_capacity_the_store_drops_the_oldest_and_the_next_birth_announces_how_many()
    {
        SparkplugNode node = Node(capacity: 3);
        Read(node, "b", 10);
        for (short v = 1; v <= 6; v++)
        {
            Read(node, "a", v);
        }

        node.Store.Dropped.Should().Be(4, "seven kept changes in a store of three");
        Payload nbirth = Decode(node.Births(0)[0]);
        Payload.Types.Metric dropped = nbirth.Metrics.Single(m => m.Name == SparkplugPayloads.Dropped);
        dropped.Datatype.Should().Be((uint)SparkplugDataType.Int64);
        dropped.LongValue.Should().Be(4);
        Decode(node.TakeHistory()!).Metrics.Select(m => (short)m.IntValue).Should().Equal([4, 5], "the newest three are kept; a=6 is in the birth");
    }

    [Fact]
    public void The_history_of_a_device_that_is_not_born_waits_and_the_other_devices_go_first()
    {
        var options = new GatewayOptions();
        options.Links["plc"] = new LinkOptions();
        options.Links["plc"].Groups["a"] = new PollGroupOptions { Address = "D1", Type = "int16" };
        options.Links["plc"].Groups["c"] = new PollGroupOptions { Address = "D3", Type = "int16", Unit = 1 };
        SparkplugNode node = Node(options);
        Read(node, "c", 100, unit: 1);
        Read(node, "c", 101, unit: 1);
        node.TagChanged(new TagChange("plc", 1, "c", "D3", PlcValueType.Int16, null, TagQuality.CommError, _time.GetUtcNow(), "timeout"));
        Read(node, "a", 1);
        Read(node, "a", 2);

        node.Births(0).Select(m => m.Topic.DeviceId).Should().Equal([null, "plc-0"], "unit 1 does not answer");
        Decode(node.TakeHistory()!).Metrics.Select(m => (m.Alias, (short)m.IntValue)).Should().Equal((1UL, (short)1));
        node.TakeHistory().Should().BeNull("plc-1's changes wait for its birth");

        Read(node, "c", 102, unit: 1);
        node.TakeMessages().Select(m => (m.Topic.Type, m.Topic.DeviceId)).Should().Equal((SparkplugMessageType.DBIRTH, "plc-1"));
        SparkplugMessage history = node.TakeHistory()!;
        history.Topic.DeviceId.Should().Be("plc-1");
        Decode(history).Metrics.Select(m => (m.Alias, (short)m.IntValue)).Should().Equal((2UL, (short)100), (2UL, (short)101));
    }

    private SparkplugNode Node(GatewayOptions? options = null, TimeSpan? keepAlive = null, int capacity = 1000)
    {
        if (options is null)
        {
            options = new GatewayOptions();
            options.Links["plc"] = new LinkOptions();
            options.Links["plc"].Groups["a"] = new PollGroupOptions { Address = "D1", Type = "int16" };
            options.Links["plc"].Groups["b"] = new PollGroupOptions { Address = "D2", Type = "int16" };
        }

        var sparkplug = new SparkplugOptions
        {
            GroupId = "G",
            EdgeNodeId = "N",
            KeepAlive = keepAlive ?? TimeSpan.FromSeconds(15),
            StateDirectory = MqttGatewayConfig.NewStateDirectory(),
            StoreAndForward = { Capacity = capacity },
        };
        SparkplugHistory history = SparkplugHistory.Open(sparkplug, Path.GetTempPath(), _time, NullLogger.Instance);
        _histories.Add(history);
        return new SparkplugNode(sparkplug, new Outputs.TagCatalog(options), history, _time);
    }

    /// <summary>A good read of a tag, 100 ms after the last.</summary>
    private void Read(SparkplugNode node, string tag, short value, int unit = 0)
    {
        _time.Advance(TimeSpan.FromMilliseconds(100));
        node.TagChanged(new TagChange("plc", unit, tag, "D1", PlcValueType.Int16, value, TagQuality.Good, _time.GetUtcNow()));
    }

    private static Payload Decode(SparkplugMessage message) => Payload.Parser.ParseFrom(message.Payload);
}
