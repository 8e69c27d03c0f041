using System.Text;
using BenchmarkDotNet.Attributes;
using Microsoft.Extensions.Logging.Abstractions;
using OmronHostLink.Gateway.Mqtt;
using OmronHostLink.Gateway.Queue;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// What a message's life in the gateway's outage queue costs (queued by a link, then removed on the broker's
/// acknowledgement): in memory only, with the count of unsent messages kept in a memory-mapped file (the default), and
/// with the durable queue (a SQLite row written and deleted). The link pays the first half, the publisher the second.
/// </summary>
[MemoryDiagnoser]
public class OutboundQueueBenchmarks
{
    private readonly byte[] _payload = Encoding.UTF8.GetBytes("""{"value":[120,-340,560,780],"type":"int16","quality":"good","time":"2025-01-31T08:00:00.125Z","address":"D100"}""");
    private string _directory = "";
    private IDisposable? _journal;
    private OutboundQueue _queue = null!;

    /// <summary>memory, unsent-count or durable.</summary>
    [Params("memory", "unsent-count", "durable")]
    public string Journal { get; set; } = "memory";

    [GlobalSetup]
    public void Setup()
    {
        _directory = Directory.CreateTempSubdirectory("ohl-queue-bench-").FullName;
        IOutboundJournal? journal = Journal switch
        {
            "unsent-count" => UnsentRecord.Open(Path.Combine(_directory, "bench.unsent")),
            "durable" => SqliteOutboundJournal.Open(Path.Combine(_directory, "bench.queue.db"), NullLogger.Instance),
            _ => null,
        };
        _journal = journal as IDisposable;
        _queue = new OutboundQueue(10_000, journal, long.MaxValue, Journal == "durable" ? TimeSpan.FromDays(7) : null, TimeProvider.System);
    }

    [GlobalCleanup]
    public void Cleanup()
    {
        _journal?.Dispose();
        Directory.Delete(_directory, recursive: true);
    }

    [Benchmark]
    public long EnqueueThenAcknowledge()
    {
        var message = new OutboundMessage("plant1/line1/0/levels", _payload, Retain: true);
        _queue.Enqueue(message);
        _queue.TryPeek(out OutboundMessage? head);
        return _queue.Remove(head!);
    }
}
