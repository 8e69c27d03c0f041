using OmronHostLink.Gateway.Sparkplug;

namespace OmronHostLink.Gateway.Tests.Sparkplug;

public sealed class SparkplugTopicTests
{
    [Fact]
    public void Node_and_device_topics_are_spelled_as_the_specification_does()
    {
        new SparkplugTopic("Plant1", SparkplugMessageType.NBIRTH, "gateway1").ToString().Should().Be("spBv1.0/Plant1/NBIRTH/gateway1");
        new SparkplugTopic("Plant1", SparkplugMessageType.DDATA, "gateway1", "line1-unit03").ToString().Should().Be("spBv1.0/Plant1/DDATA/gateway1/line1-unit03");
    }

    [Theory]
    [InlineData("spBv1.0/Plant1/DCMD/gateway1/line1-unit03", nameof(SparkplugMessageType.DCMD), "line1-unit03")]
    [InlineData("spBv1.0/Plant1/NCMD/gateway1", nameof(SparkplugMessageType.NCMD), null)]
    public void Commands_are_read_back(string text, string type, string? device)
    {
        SparkplugTopic.TryParse(text, out SparkplugTopic? topic).Should().BeTrue();
        topic!.Type.Should().Be(Enum.Parse<SparkplugMessageType>(type));
        topic.GroupId.Should().Be("Plant1");
        topic.EdgeNodeId.Should().Be("gateway1");
        topic.DeviceId.Should().Be(device);
    }

    [Theory]
    [InlineData("spBv1.0/Plant1/DCMD")]
    [InlineData("spAv1.0/Plant1/DCMD/gateway1")]
    [InlineData("spBv1.0/Plant1/dcmd/gateway1")]
    [InlineData("spBv1.0/Plant1/STATE/gateway1")]
    [InlineData("spBv1.0//DCMD/gateway1")]
    [InlineData("spBv1.0/Plant1/DCMD/gateway1/a/b")]
    public void Anything_else_is_not_a_Sparkplug_node_or_device_topic(string text)
        => SparkplugTopic.TryParse(text, out _).Should().BeFalse();

    [Theory]
    [InlineData("Plant/1", "'/'")]
    [InlineData("Plant+", "'+'")]
    [InlineData("#", "'#'")]
    [InlineData(" ", "empty")]
    public void An_id_with_a_topic_separator_or_wildcard_is_refused(string id, string reason)
        => SparkplugTopic.Check(id).Should().Contain(reason);

    [Fact]
    public void The_sequence_runs_0_to_255_and_wraps()
    {
        var seq = new SparkplugSequence();
        Enumerable.Range(0, 258).Select(_ => seq.Next()).Should().Equal(Enumerable.Range(0, 256).Select(i => (ulong)i).Concat([0UL, 1UL]));
        seq.Reset();
        seq.Next().Should().Be(0);
    }
}
