using System.Text;
using System.Text.Json;
using Microsoft.Extensions.Logging.Abstractions;
using Microsoft.Extensions.Time.Testing;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Gateway.Tests.Mqtt;

/// <summary>
/// The outage queue's record outside the process: the durable queue (SQLite) and the count of unsent messages, each
/// closed and opened again as a new run would.
/// </summary>
public sealed class DurableQueueTests : IDisposable
{
    private readonly string _directory = Directory.CreateTempSubdirectory("ohl-queue-").FullName;
    private readonly FakeTimeProvider _time = new(new DateTimeOffset(2025, 3, 1, 8, 0, 0, TimeSpan.Zero));

    private string DatabasePath => Path.Combine(_directory, "gateway.queue.db");

    public void Dispose() => Directory.Delete(_directory, recursive: true);

    [Fact]
    public void The_next_run_gets_every_unacknowledged_message_in_order_with_its_topic_payload_retain_and_correlation()
    {
        using (SqliteOutboundJournal journal = Open())
        {
            OutboundQueue queue = Queue(journal);
            queue.Enqueue(new OutboundMessage("t/a", Bytes("1"), Retain: true));
            queue.Enqueue(new OutboundMessage("t/b", Bytes("2"), Retain: true));
            queue.Enqueue(new OutboundMessage("t/reply", Bytes("3"), Retain: false, CorrelationData: [7, 8]));
            queue.Enqueue(new OutboundMessage("t/a", Bytes("4"), Retain: true));
            queue.TryPeek(out OutboundMessage? head).Should().BeTrue();
            queue.Remove(head!); // the broker acknowledged "1"
        }

        using (SqliteOutboundJournal journal = Open())
        {
            OutboundQueue queue = Queue(journal);
            queue.Restored.Should().Be(3);
            queue.HasPending("t/a").Should().BeTrue("the restored messages hold back the republishing of their topics");
            queue.Enqueue(new OutboundMessage("t/c", Bytes("5"), Retain: true));

            List<OutboundMessage> sent = Drain(queue);
            sent.Select(m => Text(m.Payload)).Should().Equal("2", "3", "4", "5");
            sent.Select(m => m.Topic).Should().Equal("t/b", "t/reply", "t/a", "t/c");
            sent.Select(m => m.Retain).Should().Equal(true, false, true, true);
            sent[1].CorrelationData.Should().Equal([7, 8]);
            sent.Select(m => m.Sequence).Should().BeInAscendingOrder("a new message is queued after the restored ones");
        }

        using (SqliteOutboundJournal journal = Open())
        {
            Queue(journal).Restored.Should().Be(0, "every message sent and acknowledged is gone from the database");
        }
    }

    [Fact]
    public void Beyond_its_size_the_oldest_are_dropped_and_gone_from_the_database()
    {
        using (SqliteOutboundJournal journal = Open())
        {
            // Each message is 32 + 1 + 100 bytes: three fit in 400.
            var queue = new OutboundQueue(1000, journal, maxBytes: 400, maxAge: null, _time);
            long dropped = 0;
            queue.Dropped += n => dropped += n;
            for (int i = 0; i < 5; i++)
            {
                queue.Enqueue(new OutboundMessage("t", Encoding.ASCII.GetBytes(i.ToString(System.Globalization.CultureInfo.InvariantCulture).PadRight(100)), Retain: true));
            }

            queue.Count.Should().Be(3);
            dropped.Should().Be(2);
        }

        using (SqliteOutboundJournal journal = Open())
        {
            Drain(Queue(journal)).Select(m => Text(m.Payload).Trim()).Should().Equal("2", "3", "4");
        }
    }

    [Fact]
    public void A_message_older_than_its_age_is_dropped_while_waiting_and_when_the_next_run_finds_it()
    {
        using (SqliteOutboundJournal journal = Open())
        {
            OutboundQueue queue = Queue(journal, maxAge: TimeSpan.FromHours(1));
            long expired = 0;
            queue.Expired += n => expired += n;
            queue.Enqueue(new OutboundMessage("t", Bytes("old"), Retain: true));
            _time.Advance(TimeSpan.FromMinutes(40));
            queue.Enqueue(new OutboundMessage("t", Bytes("newer"), Retain: true));
            _time.Advance(TimeSpan.FromMinutes(21));

            queue.TryPeek(out OutboundMessage? head).Should().BeTrue();
            Text(head!.Payload).Should().Be("newer");
            expired.Should().Be(1);
            queue.TotalDropped.Should().Be(1);
        }

        _time.Advance(TimeSpan.FromMinutes(40)); // "newer" is 61 minutes old now
        using (SqliteOutboundJournal journal = Open())
        {
            OutboundQueue queue = Queue(journal, maxAge: TimeSpan.FromHours(1));
            queue.RestoredExpired.Should().Be(1);
            queue.Count.Should().Be(0);
        }
    }

    [Fact]
    public void A_second_gateway_cannot_share_the_database_and_a_file_that_is_no_database_is_named()
    {
        using (Open())
        {
            SqliteOutboundJournal.Problem(DatabasePath).Should().Contain("another process holds it");
        }

        SqliteOutboundJournal.Problem(DatabasePath).Should().BeNull("closed, it can be opened again");

        string text = Path.Combine(_directory, "notes.queue.db");
        File.WriteAllText(text, "not a database, just some text that is long enough to have a header of its own");
        SqliteOutboundJournal.Problem(text).Should().Contain("not a database");

        string underAFile = Path.Combine(text, "x.queue.db");
        SqliteOutboundJournal.Problem(underAFile).Should().NotBeNull();
    }

    [Fact]
    public void The_count_of_unsent_messages_outlives_the_run_and_is_cleared_once_announced()
    {
        string path = Path.Combine(_directory, "gateway.unsent");
        using (UnsentRecord record = UnsentRecord.Open(path))
        {
            record.PreviousLoss.Should().Be(0, "a new file");
            var queue = new OutboundQueue(100, record, long.MaxValue, null, _time);
            for (int i = 0; i < 5; i++)
            {
                queue.Enqueue(new OutboundMessage("t", Bytes(i.ToString(System.Globalization.CultureInfo.InvariantCulture)), Retain: true));
            }

            queue.TryPeek(out OutboundMessage? head);
            queue.Remove(head!);
            record.Pending.Should().Be(4);
        }

        // A run that ends (crash or not) before its announcement is acknowledged keeps the count for the next one.
        using (UnsentRecord record = UnsentRecord.Open(path))
        {
            record.PreviousLoss.Should().Be(4);
            var queue = new OutboundQueue(100, record, long.MaxValue, null, _time);
            var report = new OutboundMessage("t/status/gw/lost", Bytes("{}"), Retain: false);
            record.Announcing(report);
            queue.Enqueue(report);
            queue.Enqueue(new OutboundMessage("t", Bytes("x"), Retain: true));
            record.Pending.Should().Be(1, "the announcement is not one of the messages it counts");
        }

        using (UnsentRecord record = UnsentRecord.Open(path))
        {
            record.PreviousLoss.Should().Be(5, "the 4 not announced and the 1 left queued");
            var queue = new OutboundQueue(100, record, long.MaxValue, null, _time);
            var report = new OutboundMessage("t/status/gw/lost", Bytes("{}"), Retain: false);
            record.Announcing(report);
            queue.Enqueue(report);
            queue.TryPeek(out OutboundMessage? head);
            queue.Remove(head!); // the broker acknowledged the announcement
        }

        using (UnsentRecord record = UnsentRecord.Open(path))
        {
            record.PreviousLoss.Should().Be(0);
        }
    }

    [Fact]
    public void Messages_a_full_database_cannot_take_are_counted_as_at_risk_and_go_into_it_once_there_is_room()
    {
        string recordPath = Path.Combine(_directory, "gateway.unsent");
        int atRiskAtEnd;
        using (UnsentRecord record = UnsentRecord.Open(recordPath))
        using (SqliteOutboundJournal journal = SqliteOutboundJournal.Open(DatabasePath, NullLogger.Instance, record, maxDatabaseBytes: 64 * 1024))
        {
            // 64 KB hold fewer than 60 messages of 2 KB: the database is full, as on a full disk.
            OutboundQueue queue = Queue(journal);
            for (int i = 0; i < 60; i++)
            {
                queue.Enqueue(new OutboundMessage("t", Encoding.ASCII.GetBytes(i.ToString(System.Globalization.CultureInfo.InvariantCulture).PadRight(2000)), Retain: true));
            }

            queue.Count.Should().Be(60, "the queue keeps every message in memory");
            int atRisk = journal.MemoryOnly;
            atRisk.Should().BeInRange(1, 59);
            record.Pending.Should().Be(atRisk, "each message the database could not take is counted");

            // The broker acknowledges ten: their rows make room, and the held messages go into the database.
            for (int i = 0; i < 10; i++)
            {
                queue.TryPeek(out OutboundMessage? head).Should().BeTrue();
                queue.Remove(head!);
            }

            journal.MemoryOnly.Should().BeLessThan(atRisk);
            record.Pending.Should().Be(journal.MemoryOnly);
            atRiskAtEnd = journal.MemoryOnly;
            atRiskAtEnd.Should().BeGreaterThan(0, "ten rows do not make room for all");
        }

        // The run ends (as a crash would): the next one sends what the database holds and announces the rest as lost.
        using (UnsentRecord record = UnsentRecord.Open(recordPath))
        using (SqliteOutboundJournal journal = Open())
        {
            record.PreviousLoss.Should().Be(atRiskAtEnd);
            List<int> sent = Drain(Queue(journal)).Select(m => int.Parse(Text(m.Payload).Trim(), System.Globalization.CultureInfo.InvariantCulture)).ToList();
            sent.Should().HaveCount(50 - atRiskAtEnd).And.BeInAscendingOrder().And.OnlyHaveUniqueItems();
            sent.Should().OnlyContain(n => n >= 10, "the acknowledged ones are gone");
        }
    }

    [Fact]
    public void The_store_announces_the_previous_loss_first_and_a_durable_queue_sends_the_previous_messages_before_it()
    {
        var options = new MqttOptions { ClientId = "gw", TopicPrefix = "p", StateDirectory = _directory };
        var topics = new MqttTopics("p", "gw");
        using (var store = MqttOutboundQueue.OpenStore(options, _directory, NullLogger.Instance))
        {
            OutboundQueue queue = store.CreateQueue(options, topics, _time);
            queue.Enqueue(new OutboundMessage("p/l/0/a", Bytes("1"), Retain: true));
            queue.Enqueue(new OutboundMessage("p/l/0/a", Bytes("2"), Retain: true));
        }

        options.DurableQueue.Enabled = true;
        using (var store = MqttOutboundQueue.OpenStore(options, _directory, NullLogger.Instance))
        {
            OutboundQueue queue = store.CreateQueue(options, topics, _time);
            queue.Enqueue(new OutboundMessage("p/l/0/a", Bytes("3"), Retain: true));
        }

        using (var store = MqttOutboundQueue.OpenStore(options, _directory, NullLogger.Instance))
        {
            List<OutboundMessage> sent = Drain(store.CreateQueue(options, topics, _time));
            sent.Select(m => m.Topic).Should().Equal("p/status/gw/lost", "p/l/0/a");
            using JsonDocument report = JsonDocument.Parse(sent[0].Payload);
            report.RootElement.GetProperty("lost").GetInt64().Should().Be(2);
            report.RootElement.GetProperty("time").GetString().Should().Be("2025-03-01T08:00:00.000Z");
            Text(sent[1].Payload).Should().Be("3");
        }

        File.Exists(Path.Combine(_directory, "gw.queue.db")).Should().BeTrue();
        File.Exists(Path.Combine(_directory, "gw.unsent")).Should().BeTrue();
    }

    private SqliteOutboundJournal Open() => SqliteOutboundJournal.Open(DatabasePath, NullLogger.Instance);

    private OutboundQueue Queue(SqliteOutboundJournal journal, TimeSpan? maxAge = null) => new(1000, journal, long.MaxValue, maxAge, _time);

    private static List<OutboundMessage> Drain(OutboundQueue queue)
    {
        var sent = new List<OutboundMessage>();
        while (queue.TryPeek(out OutboundMessage? head))
        {
            sent.Add(head);
            queue.Remove(head);
        }

        return sent;
    }

    private static byte[] Bytes(string text) => Encoding.UTF8.GetBytes(text);

    private static string Text(byte[] bytes) => Encoding.UTF8.GetString(bytes);
}
