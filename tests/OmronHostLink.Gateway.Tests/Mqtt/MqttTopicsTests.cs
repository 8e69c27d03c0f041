using OmronHostLink.Gateway.Mqtt;

namespace OmronHostLink.Gateway.Tests.Mqtt;

public sealed class MqttTopicsTests
{
    private readonly MqttTopics _topics = new("plant/a", "worker-1");

    [Fact]
    public void Topics_follow_the_contract()
    {
        _topics.Tag("line1", 3, "levels").Should().Be("plant/a/line1/3/levels");
        _topics.LinkStatus("line1").Should().Be("plant/a/line1/status");
        _topics.WorkerStatus.Should().Be("plant/a/status/worker-1");
        _topics.CommandFilter("line1").Should().Be("plant/a/line1/+/+/set");
        MqttTopics.ResultTopic("plant/a/line1/3/levels/set").Should().Be("plant/a/line1/3/levels/set/result");
    }

    [Theory]
    [InlineData("plant/a/line1/3/levels/set", true, "line1", 3, "levels")]
    [InlineData("plant/a/line1/03/levels/set", false, "", -1, "")]
    [InlineData("plant/a/line1/x/levels/set", false, "", -1, "")]
    [InlineData("plant/a/line1/-1/levels/set", false, "", -1, "")]
    [InlineData("plant/a/line1/3/levels", false, "", -1, "")]
    [InlineData("plant/a/line1/3/levels/set/result", false, "", -1, "")]
    [InlineData("plant/b/line1/3/levels/set", false, "", -1, "")]
    [InlineData("plant/aa/line1/3/levels/set", false, "", -1, "")]
    public void Command_topics_are_parsed_strictly(string topic, bool ok, string link, int unit, string tag)
    {
        _topics.TryParseCommand(topic, out string l, out int u, out string t).Should().Be(ok);
        if (ok)
        {
            (l, u, t).Should().Be((link, unit, tag));
        }
    }

    [Theory]
    [InlineData("line1", null)]
    [InlineData("", "is empty")]
    [InlineData("a/b", "holds '/'")]
    [InlineData("a+", "holds '+'")]
    [InlineData("#", "holds '#'")]
    public void Names_that_cannot_be_a_topic_level_are_named(string level, string? problem)
    {
        string? found = MqttTopics.LevelProblem(level);
        if (problem is null)
        {
            found.Should().BeNull();
        }
        else
        {
            found.Should().StartWith(problem);
        }
    }
}
