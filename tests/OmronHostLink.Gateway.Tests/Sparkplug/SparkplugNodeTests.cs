using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Gateway.Configuration;
using OmronHostLink.Gateway.Sparkplug;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

/// <summary>The edge node's devices and messages, as the polling feeds them.</summary>
public sealed class SparkplugNodeTests
{
    private static readonly DateTimeOffset T0 = new(2025, 3, 1, 8, 0, 0, TimeSpan.Zero);

    [Fact]
    public void Aliases_are_numbered_by_link_unit_and_tag_name_whatever_the_order_the_tags_come_in()
    {
        var options = new GatewayOptions();
        options.Links["b"] = new LinkOptions();
        options.Links["b"].Groups["x"] = new PollGroupOptions { Address = "D1" };
        options.Links["a"] = new LinkOptions();
        options.Links["a"].Groups["zeta"] = new PollGroupOptions { Address = "D1" };
        options.Links["a"].Groups["beta"] = new PollGroupOptions { Address = "D2", Count = 2 };
        options.Links["a"].Groups["other"] = new PollGroupOptions { Address = "D1", Unit = 1 };
        // A row of a tag file comes after the groups, whatever its name.
        options.Links["a"].Groups["Alpha"] = new PollGroupOptions { Address = "D5", Row = "TagFiles:0:Path tags.csv, line 2" };

        IReadOnlyList<SparkplugDevice> devices = SparkplugDevice.FromCatalog(new Outputs.TagCatalog(options));

        devices.Select(d => d.Id).Should().Equal("a-0", "a-1", "b-0");
        devices[0].Metrics.Select(m => (m.Name, m.Alias)).Should().Equal(("Alpha", 1UL), ("beta/0", 2UL), ("beta/1", 3UL), ("zeta", 4UL));
        devices[1].Metrics.Select(m => (m.Name, m.Alias)).Should().Equal(("other", 5UL));
        devices[2].Metrics.Select(m => (m.Name, m.Alias)).Should().Equal(("x", 6UL));
    }

    [Fact]
    public void A_unit_that_stops_answering_is_a_device_death_without_data_of_bad_quality_before_it()
    {
        var options = new GatewayOptions();
        options.Links["plc"] = new LinkOptions();
        options.Links["plc"].Groups["a"] = new PollGroupOptions { Address = "D1", Type = "int16" };
        options.Links["plc"].Groups["b"] = new PollGroupOptions { Address = "D2", Type = "int16" };
        var node = new SparkplugNode(new SparkplugOptions { GroupId = "G", EdgeNodeId = "N" }, new Outputs.TagCatalog(options), new FakeTimeProvider(T0));
        node.TagChanged(Change("a", (short)1, TagQuality.Good));
        node.TagChanged(Change("b", (short)2, TagQuality.Good));
        node.Births(0).Select(m => m.Topic.Type).Should().Equal(SparkplugMessageType.NBIRTH, SparkplugMessageType.DBIRTH);

        // The polling reports every tag of the unit comm-error, then the unit: the publisher may take its messages in between.
        node.TagChanged(Change("a", null, TagQuality.CommError));
        List<SparkplugMessage> first = node.TakeMessages(connected: true);
        node.TagChanged(Change("b", null, TagQuality.CommError));
        node.UnitChanged("plc", 0, UnitState.CommError, "timeout");
        List<SparkplugMessage> then = node.TakeMessages(connected: true);

        first.Select(m => (m.Topic.Type, m.Topic.DeviceId)).Should().Equal((SparkplugMessageType.DDEATH, "plc-0"));
        then.Should().BeEmpty("the death said it all");
    }

    private static TagChange Change(string tag, object? value, TagQuality quality)
        => new("plc", 0, tag, "D1", PlcValueType.Int16, value, quality, T0, quality == TagQuality.Good ? null : "timeout");
}
