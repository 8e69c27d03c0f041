using System.Text;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Tests.Mqtt;

public sealed class OutboundQueueTests
{
    private static OutboundMessage M(string topic, string payload = "x") => new(topic, Encoding.UTF8.GetBytes(payload), Retain: true);

    [Fact]
    public void A_full_queue_drops_the_oldest_and_counts_one_episode_until_it_drains()
    {
        var queue = new OutboundQueue(3);
        int episodes = 0;
        long dropped = 0;
        queue.OverflowStarted += () => episodes++;
        queue.Dropped += n => dropped += n;

        for (int i = 1; i <= 7; i++)
        {
            queue.Enqueue(M("t", i.ToString(System.Globalization.CultureInfo.InvariantCulture)));
        }

        queue.Count.Should().Be(3);
        episodes.Should().Be(1);
        dropped.Should().Be(4);
        queue.TotalDropped.Should().Be(4);
        var sent = new List<string>();
        long episode = 0;
        while (queue.TryPeek(out OutboundMessage? head))
        {
            sent.Add(Encoding.UTF8.GetString(head.Payload));
            episode += queue.Remove(head);
        }

        sent.Should().Equal("5", "6", "7");
        episode.Should().Be(4, "the episode's count is reported once, when the queue is empty again");
        queue.EndOverflowEpisode().Should().Be(0);

        queue.Enqueue(M("t"));
        queue.Enqueue(M("t"));
        queue.Enqueue(M("t"));
        queue.Enqueue(M("t"));
        episodes.Should().Be(2, "a new overflow is a new episode");
        queue.EndOverflowEpisode().Should().Be(1);
    }

    [Fact]
    public void A_message_stays_queued_until_removed_after_its_acknowledgement()
    {
        var queue = new OutboundQueue(10);
        queue.Enqueue(M("a"));
        queue.Enqueue(M("b"));

        queue.TryPeek(out OutboundMessage? first).Should().BeTrue();
        queue.TryPeek(out OutboundMessage? again).Should().BeTrue();
        again.Should().BeSameAs(first, "peeking does not remove: a send that fails is tried again with the same message");
        queue.Count.Should().Be(2);

        queue.Remove(first!);
        queue.TryPeek(out OutboundMessage? second).Should().BeTrue();
        second!.Topic.Should().Be("b");
    }

    [Fact]
    public void A_message_dropped_while_in_flight_does_not_take_the_next_one_with_it()
    {
        var queue = new OutboundQueue(2);
        queue.Enqueue(M("a"));
        queue.Enqueue(M("b"));
        queue.TryPeek(out OutboundMessage? inFlight);

        queue.Enqueue(M("c")); // drops "a", the one in flight
        queue.Remove(inFlight!);

        queue.Count.Should().Be(2);
        queue.TryPeek(out OutboundMessage? head);
        head!.Topic.Should().Be("b");
    }

    [Fact]
    public void Pending_topics_are_known_until_their_last_message_leaves()
    {
        var queue = new OutboundQueue(3);
        queue.Enqueue(M("a"));
        queue.Enqueue(M("a"));
        queue.Enqueue(M("b"));
        queue.HasPending("a").Should().BeTrue();
        queue.HasPending("c").Should().BeFalse();

        queue.Enqueue(M("c")); // drops the first "a"
        queue.HasPending("a").Should().BeTrue();
        queue.TryPeek(out OutboundMessage? head);
        queue.Remove(head!);
        queue.HasPending("a").Should().BeFalse();
        queue.HasPending("b").Should().BeTrue();
    }

    [Fact]
    public async Task A_waiting_publisher_wakes_when_a_message_is_queued()
    {
        var queue = new OutboundQueue(3);
        ValueTask wait = queue.WaitAsync(CancellationToken.None);
        wait.IsCompleted.Should().BeFalse();

        queue.Enqueue(M("a"));

        await wait.AsTask().WaitAsync(TimeSpan.FromSeconds(5));
        await queue.WaitAsync(CancellationToken.None).AsTask().WaitAsync(TimeSpan.FromSeconds(5)); // a message waits: at once
    }

    [Fact]
    public void Enqueueing_never_blocks_even_with_nobody_draining()
    {
        var queue = new OutboundQueue(100);
        for (int i = 0; i < 100_000; i++)
        {
            queue.Enqueue(M("t" + (i % 10)));
        }

        queue.Count.Should().Be(100);
        queue.TotalDropped.Should().Be(99_900);
    }
}
