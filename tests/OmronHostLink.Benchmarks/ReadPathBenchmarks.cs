using BenchmarkDotNet.Attributes;
using OmronHostLink.Protocol.CMode;

namespace OmronHostLink.Benchmarks;

/// <summary>
/// The whole per-transaction cost of <see cref="HostLinkUnit.ReadWordsAsync(string, int, CancellationToken)"/>: client,
/// link, frame channel, deadline, decoding, against an in-process stream that answers every RD at once. With
/// <see cref="AnswerOnThreadPool"/> the answer arrives from a thread-pool thread, as a socket's or serial port's does,
/// so the figure includes the thread hand-offs between the bytes arriving and the caller resuming.
/// </summary>
[MemoryDiagnoser]
[MedianColumn]
public class ReadPathBenchmarks
{
    private readonly ManualResetEventSlim _done = new();
    private HostLinkClient _client = null!;
    private Action _signal = null!;

    [Params(1, 30)]
    public int Words { get; set; }

    [Params(false, true)]
    public bool AnswerOnThreadPool { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        StartListening();
        var stream = new AnsweringStream(Words, AnswerOnThreadPool);
        _client = HostLinkClient.ForStream(stream, new HostLinkClientOptions { ReadRetries = 0 });
        _signal = _done.Set;
        ReadWords();
    }

    [GlobalCleanup]
    public void Cleanup()
    {
        _client.DisposeAsync().AsTask().GetAwaiter().GetResult();
        StopListening();
    }

    /// <summary>One read, waited for with a completion callback (no thread blocks).</summary>
    [Benchmark]
    public ushort[] ReadWords()
    {
        Task<ushort[]> read = _client.ReadWordsAsync("D100", Words);
        if (!read.IsCompleted)
        {
            _done.Reset();
            read.GetAwaiter().UnsafeOnCompleted(_signal);
            _done.Wait();
        }

        return read.GetAwaiter().GetResult();
    }

    /// <summary>Attaches telemetry listeners before the client is made; none here.</summary>
    protected virtual void StartListening()
    {
    }

    /// <summary>Detaches what <see cref="StartListening"/> attached.</summary>
    protected virtual void StopListening()
    {
    }

    /// <summary>A PLC in a stream: every write is taken as an RD command and answered with a fixed answer of the right size.</summary>
    internal sealed class AnsweringStream : PassThroughStream, IThreadPoolWorkItem
    {
        private readonly byte[] _answer;
        private readonly bool _onThreadPool;
        private readonly object _lock = new();
        private readonly Source _source;
        private System.Threading.Tasks.Sources.ManualResetValueTaskSourceCore<int> _read;
        private Memory<byte> _pendingBuffer;
        private bool _pending;
        private int _answered = -1;

        public AnsweringStream(int words, bool onThreadPool)
            : base(Null)
        {
            _onThreadPool = onThreadPool;
            var text = new byte[2 + (4 * words)];
            text.AsSpan().Fill((byte)'0');
            var message = new byte[CModeCommand.PrefixLength + text.Length];
            "@00RD"u8.CopyTo(message);
            text.CopyTo(message.AsSpan(CModeCommand.PrefixLength));
            _answer = new byte[message.Length + 4];
            int length = Protocol.FrameWriter.WriteFrame(message, final: true, _answer);
            Array.Resize(ref _answer, length);
            _read.RunContinuationsAsynchronously = false;
            _source = new Source(this);
        }

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            if (_onThreadPool)
            {
                ThreadPool.UnsafeQueueUserWorkItem(this, preferLocal: false);
            }
            else
            {
                Answer();
            }

            return default;
        }

        public void Execute() => Answer();

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
        {
            lock (_lock)
            {
                if (_answered >= 0)
                {
                    int n = Copy(buffer);
                    return new ValueTask<int>(n);
                }

                _pendingBuffer = buffer;
                _pending = true;
                _read.Reset();
                return new ValueTask<int>(_source, _read.Version);
            }
        }

        /// <summary>Closing ends a pending read with end of stream, as a closed socket does.</summary>
        protected override void Dispose(bool disposing)
        {
            bool pending;
            lock (_lock)
            {
                pending = _pending;
                _pending = false;
            }

            if (pending)
            {
                _read.SetResult(0);
            }

            base.Dispose(disposing);
        }

        private void Answer()
        {
            int n = -1;
            lock (_lock)
            {
                _answered = 0;
                if (_pending)
                {
                    _pending = false;
                    n = Copy(_pendingBuffer);
                    _pendingBuffer = default;
                }
            }

            if (n >= 0)
            {
                _read.SetResult(n);
            }
        }

        private int ReadResult(short token) => _read.GetResult(token);

        private System.Threading.Tasks.Sources.ValueTaskSourceStatus ReadStatus(short token) => _read.GetStatus(token);

        private void OnReadCompleted(Action<object?> continuation, object? state, short token, System.Threading.Tasks.Sources.ValueTaskSourceOnCompletedFlags flags)
            => _read.OnCompleted(continuation, state, token, flags);

        private int Copy(Memory<byte> buffer)
        {
            int n = Math.Min(buffer.Length, _answer.Length - _answered);
            _answer.AsSpan(_answered, n).CopyTo(buffer.Span);
            _answered += n;
            if (_answered == _answer.Length)
            {
                _answered = -1;
            }

            return n;
        }

        /// <summary>The pending read's source, one per stream.</summary>
        private sealed class Source(AnsweringStream owner) : System.Threading.Tasks.Sources.IValueTaskSource<int>
        {
            public int GetResult(short token) => owner.ReadResult(token);

            public System.Threading.Tasks.Sources.ValueTaskSourceStatus GetStatus(short token) => owner.ReadStatus(token);

            public void OnCompleted(Action<object?> continuation, object? state, short token, System.Threading.Tasks.Sources.ValueTaskSourceOnCompletedFlags flags)
                => owner.OnReadCompleted(continuation, state, token, flags);
        }
    }
}
