using System.Diagnostics;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// Every change the writer made and every value the subscriber received, per tag. Change k of a tag sets its value to
/// k + 1 (the tags start at 0), so a received value names the change it carries. Times are
/// <see cref="Stopwatch"/> timestamps; read times are the payload's <c>time</c> (the worker's clock, UTC).
/// </summary>
internal sealed class ChangeLedger
{
    private readonly long[][] _written;
    private readonly long[][] _received;
    private readonly double[][] _readToReceiveMs;
    private readonly int[] _writtenCount;
    private readonly int[] _lastValue;
    private readonly bool[] _seen;
    private long _duplicates;
    private long _outOfOrder;
    private long _notGood;
    private int _seenCount;

    public ChangeLedger(int tags, int maxChangesPerTag)
    {
        if (maxChangesPerTag >= ushort.MaxValue)
        {
            throw new ArgumentOutOfRangeException(nameof(maxChangesPerTag), maxChangesPerTag, "A word tag counts at most 65535 changes.");
        }

        Tags = tags;
        _written = Enumerable.Range(0, tags).Select(_ => new long[maxChangesPerTag]).ToArray();
        _received = Enumerable.Range(0, tags).Select(_ => new long[maxChangesPerTag]).ToArray();
        _readToReceiveMs = Enumerable.Range(0, tags).Select(_ => new double[maxChangesPerTag]).ToArray();
        _writtenCount = new int[tags];
        _lastValue = new int[tags];
        _seen = new bool[tags];
    }

    public int Tags { get; }

    /// <summary>Tags of which at least one good value has arrived (the initial one counts).</summary>
    public int SeenTags => Volatile.Read(ref _seenCount);

    /// <summary>Messages that repeated a value already received (at-least-once delivery allows it).</summary>
    public long Duplicates => Interlocked.Read(ref _duplicates);

    /// <summary>Messages with a value older than one already received on the topic (must be 0).</summary>
    public long OutOfOrder => Interlocked.Read(ref _outOfOrder);

    /// <summary>Messages whose quality was not good.</summary>
    public long NotGood => Interlocked.Read(ref _notGood);

    /// <summary>The writer's next change of <paramref name="tag"/>: the value to write (the change is recorded by <see cref="Written"/>).</summary>
    public ushort NextValue(int tag) => (ushort)(_writtenCount[tag] + 1);

    /// <summary>Records that the writer has just written <see cref="NextValue"/> to <paramref name="tag"/>.</summary>
    public void Written(int tag, long timestamp)
    {
        int k = _writtenCount[tag];
        Volatile.Write(ref _written[tag][k], timestamp);
        Volatile.Write(ref _writtenCount[tag], k + 1);
    }

    /// <summary>Records a message on <paramref name="tag"/>'s topic (called from the subscriber's one receive loop).</summary>
    public void Received(int tag, int value, bool good, long timestamp, double readToReceiveMs)
    {
        if (!good)
        {
            Interlocked.Increment(ref _notGood);
            return;
        }

        if (!_seen[tag])
        {
            _seen[tag] = true;
            Interlocked.Increment(ref _seenCount);
        }

        if (value < _lastValue[tag])
        {
            Interlocked.Increment(ref _outOfOrder);
        }

        _lastValue[tag] = Math.Max(_lastValue[tag], value);
        int k = value - 1;
        if (k < 0 || k >= _received[tag].Length)
        {
            return;
        }

        if (_received[tag][k] != 0)
        {
            Interlocked.Increment(ref _duplicates);
            return;
        }

        _received[tag][k] = timestamp;
        _readToReceiveMs[tag][k] = readToReceiveMs;
    }

    /// <summary>Changes made so far, over all tags.</summary>
    public long ChangesWritten()
    {
        long sum = 0;
        for (int t = 0; t < Tags; t++)
        {
            sum += Volatile.Read(ref _writtenCount[t]);
        }

        return sum;
    }

    /// <summary>Changes made whose value has not arrived (yet).</summary>
    public long Missing()
    {
        long missing = 0;
        for (int t = 0; t < Tags; t++)
        {
            int n = Volatile.Read(ref _writtenCount[t]);
            for (int k = 0; k < n; k++)
            {
                if (Volatile.Read(ref _received[t][k]) == 0)
                {
                    missing++;
                }
            }
        }

        return missing;
    }

    /// <summary>Change-to-subscriber and read-to-subscriber times (ms) of the changes that arrived.</summary>
    public (double[] ChangeToReceive, double[] ReadToReceive) Latencies()
    {
        var change = new List<double>();
        var read = new List<double>();
        for (int t = 0; t < Tags; t++)
        {
            int n = Volatile.Read(ref _writtenCount[t]);
            for (int k = 0; k < n; k++)
            {
                long received = Volatile.Read(ref _received[t][k]);
                if (received != 0)
                {
                    change.Add((received - _written[t][k]) * 1000.0 / Stopwatch.Frequency);
                    read.Add(_readToReceiveMs[t][k]);
                }
            }
        }

        change.Sort();
        read.Sort();
        return (change.ToArray(), read.ToArray());
    }
}
