using System.Runtime.CompilerServices;
using System.Threading.Tasks.Sources;
using Microsoft.Extensions.Logging;
using OmronHostLink.Capture;
using OmronHostLink.Protocol;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The bytes of one open stream, cut into frames: a receive loop that keeps one read pending on the stream at all
/// times and buffers what arrives, frame reads with a per-frame deadline, and writes.
/// </summary>
/// <remarks>
/// The stream read is never cancelled (no transport has to support cancelling a pending read), and bytes that arrive
/// between transactions are kept until resynchronisation discards them. The receive loop is a chain of read
/// completions, not a thread: when bytes complete a read, the next read is issued first and then the waiting frame
/// read is resumed on that same thread, so the caller resumes with one thread hand-off (the stream's own completion)
/// and anything the caller then blocks on cannot stall the reception of later bytes. The bytes wait in a
/// <see cref="ReceiveBuffer"/>, bounded: past 64 KiB without a frame being taken the loop stops reading until the buffer
/// drains (a line that floods the port costs no CPU while nobody reads).
/// <para>
/// Not a <c>System.IO.Pipelines</c> pipe: its reader resumes either inline in the writer's flush, where the loop could
/// not read on until the caller returns (a caller that blocks would stall reception), or through a scheduler, one more
/// hand-off and a work item per chunk; a pipe-based link measured slower and allocated more per read
/// (docs/performance.md, read path).
/// </para>
/// <para>
/// One transaction at a time (the connection's gate): <see cref="Begin"/>, frame reads and writes, <see cref="End"/>.
/// The deadline is one timer from the <see cref="TimeProvider"/>, re-armed for each frame, so a transaction allocates
/// nothing for it. The waiting frame read is this object, one reusable <see cref="IValueTaskSource{TResult}"/>: a task
/// completion source per wait measured 70–100 B more a read when the answer arrives on another thread
/// (docs/performance.md, read path).
/// </para>
/// </remarks>
internal sealed class FrameChannel : IValueTaskSource<bool>
{
    internal const int PauseThreshold = 64 * 1024;
    private const int ResumeThreshold = 32 * 1024;

    private readonly object _lock = new();
    private readonly Stream _stream;
    private readonly string _description;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly ITimer _deadline;
    private readonly Action _onReadCompleted;
    private readonly byte[] _readBuffer = new byte[512];
    private readonly byte[] _frame = new byte[FrameReader.MaxFrameLength + 2];
    private readonly CancellationTokenSource _stopReading = new();
    private readonly TaskCompletionSource<bool> _readingStopped = new(TaskCreationOptions.RunContinuationsAsynchronously);

    // Guarded by _lock.
    private readonly ReceiveBuffer _received = new();
    private bool _reading;
    private bool _closed;
    private bool _stopped;
    private HostLinkConnectionException? _closedReason;
    private HostLinkConnectionException? _abortReason;
    private bool _waiting;
    private bool _deadlinePassed;
    private bool _cancelled;
    private long _deadlineArmedAt;
    private TimeSpan _deadlineTimeout;
    private long _receivedAt;

    private ManualResetValueTaskSourceCore<bool> _waiter;
    private ConfiguredValueTaskAwaitable<int>.ConfiguredValueTaskAwaiter _pendingRead;
    private CancellationToken _callerToken;
    private CancellationTokenRegistration _callerRegistration;
    private CancellationTokenSource _writeAbort = new();
    private int _tapUnit = -1;
    private string? _tapHeader;

    public FrameChannel(Stream stream, string description, ILogger logger, TimeProvider time)
    {
        _stream = stream;
        _description = description;
        _logger = logger;
        _time = time;
        _onReadCompleted = OnReadCompleted;
        _waiter.RunContinuationsAsynchronously = false;

        // The timer's callbacks need nothing from the caller's execution context (and must not keep its async locals alive).
        using (ExecutionContext.SuppressFlow())
        {
            _deadline = time.CreateTimer(static s => ((FrameChannel)s!).OnDeadline(), this, Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
        }
    }

    /// <summary>The link's frame tap (trace file, frame observer), or null; told of every frame sent and taken.</summary>
    public FrameTap? Tap { get; set; }

    /// <summary>The last frame read by <see cref="ReadFrameAsync"/>.</summary>
    public ReadOnlySpan<byte> Frame(int length) => _frame.AsSpan(0, length);

    /// <summary>
    /// When (on the link's clock) the bytes that completed the last frame read had arrived, at the latest: the time of
    /// the last read from the stream before the frame was taken.
    /// </summary>
    public long FrameArrivedAt { get; private set; }

    /// <summary>Whether a frame has started (<c>@</c>) in the bytes received and not yet taken.</summary>
    public bool HoldsFrameStart
    {
        get
        {
            lock (_lock)
            {
                return _received.HoldsFrameStart();
            }
        }
    }

    /// <summary>Bytes received and not yet taken: between exchanges, anything here came while no command was outstanding.</summary>
    public int Held
    {
        get
        {
            lock (_lock)
            {
                return _received.Held;
            }
        }
    }

    /// <summary>Starts the receive loop.</summary>
    public void Start()
    {
        lock (_lock)
        {
            _reading = true;
        }

        ReadLoop();
    }

    /// <summary>
    /// Starts a transaction: the caller's token now cancels frame reads and writes; <paramref name="unit"/> and
    /// <paramref name="header"/> name the exchange's later frames to the tap.
    /// </summary>
    public void Begin(CancellationToken cancellationToken, int unit = -1, string? header = null)
    {
        _tapUnit = unit;
        _tapHeader = header;
        lock (_lock)
        {
            _cancelled = false;
            _deadlinePassed = false;
        }

        _callerToken = cancellationToken;
        if (cancellationToken.CanBeCanceled)
        {
#if NET
            _callerRegistration = cancellationToken.UnsafeRegister(static s => ((FrameChannel)s!).OnCallerCancelled(), this);
#else
            _callerRegistration = cancellationToken.Register(static s => ((FrameChannel)s!).OnCallerCancelled(), this);
#endif
        }
    }

    /// <summary>Ends the transaction: the deadline is disarmed and the caller's token let go.</summary>
    public void End()
    {
        _callerRegistration.Dispose();
        _callerRegistration = default;
        _callerToken = default;
        CancellationTokenSource? spent = null;
        lock (_lock)
        {
            if (_stopped)
            {
                // The link broke during the transaction: the timer and the write source are gone with the stream.
                return;
            }

            _deadline.Change(Timeout.InfiniteTimeSpan, Timeout.InfiniteTimeSpan);
            _deadlineTimeout = Timeout.InfiniteTimeSpan;
            if (_writeAbort.IsCancellationRequested)
            {
                // Only a cancelled source needs replacing: one that never fired is reused as it is.
                spent = _writeAbort;
                _writeAbort = new CancellationTokenSource();
            }
        }

        spent?.Dispose();
    }

    /// <summary>Sends bytes as they are.</summary>
    /// <exception cref="HostLinkConnectionException">The stream failed.</exception>
    /// <exception cref="OperationCanceledException">The caller cancelled.</exception>
    /// <exception cref="HostLinkTimeoutException">The frame's deadline passed before the bytes were taken.</exception>
    public async ValueTask WriteAsync(ReadOnlyMemory<byte> bytes)
    {
        Tap?.OnFrame(new TappedFrame(LineDirection.ToPlc, _time.GetUtcNow(), bytes.Span, _tapUnit, _tapHeader));
        if (_logger.IsEnabled(LogLevel.Trace))
        {
            HostLinkLog.Frame(_logger, _description, ">>", FrameText.Printable(bytes.Span));
        }

        CancellationToken token;
        CancellationTokenSource? spent = null;
        lock (_lock)
        {
            ThrowIfAbortedLocked();
            if (_writeAbort.IsCancellationRequested && !_cancelled)
            {
                // The last frame's deadline passed and the transaction goes on (a second fence): this write is a new frame.
                spent = _writeAbort;
                _writeAbort = new CancellationTokenSource();
            }

            token = _writeAbort.Token;
        }

        spent?.Dispose();

        try
        {
            await StreamCompat.WriteAsync(_stream, bytes, token).ConfigureAwait(false);
            await _stream.FlushAsync(token).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (_callerToken.IsCancellationRequested)
        {
            throw new OperationCanceledException(_callerToken);
        }
        catch (Exception e) when (AbortReason is { } reason && e is OperationCanceledException or IOException or ObjectDisposedException or System.Net.Sockets.SocketException or InvalidOperationException)
        {
            throw new HostLinkConnectionException(reason.Message, reason.InnerException);
        }
        catch (OperationCanceledException) when (Volatile.Read(ref _deadlinePassed))
        {
            throw new HostLinkTimeoutException($"Could not send to {_description} within {_deadlineTimeout.TotalMilliseconds:0} ms.", _deadlineTimeout);
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or System.Net.Sockets.SocketException or InvalidOperationException)
        {
            throw new HostLinkConnectionException($"Lost {_description} while sending: {e.Message}", e);
        }
    }

    /// <summary>
    /// Ends the channel at once, from any thread, without waiting for anything: a frame read or write in progress (and
    /// any later one) fails with a copy of <paramref name="reason"/>, the receive loop stops, and the transaction's
    /// caller resumes on the thread pool, never on the thread that aborts. The stream is the caller's to close.
    /// </summary>
    public void Abort(HostLinkConnectionException reason)
    {
        bool wake;
        lock (_lock)
        {
            if (_abortReason is not null)
            {
                return;
            }

            _abortReason = reason;
            _closedReason = reason;
            _closed = true;
            CancelWritesLocked();
            wake = TakeWaiterLocked();

            // A read still pending on the stream only lands in the buffer now; nothing waits for it to end.
            _readingStopped.TrySetResult(true);
        }

        try
        {
            _stopReading.Cancel();
        }
        catch (AggregateException)
        {
            // A stream's cancellation callback failed; the stream is being closed anyway.
        }

        if (wake)
        {
            ThreadPool.UnsafeQueueUserWorkItem(static s => ((FrameChannel)s!)._waiter.SetResult(true), this);
        }
    }

    /// <summary>Why the channel was aborted, or null.</summary>
    private HostLinkConnectionException? AbortReason
    {
        get
        {
            lock (_lock)
            {
                return _abortReason;
            }
        }
    }

    /// <summary>Waits for the next CR-terminated frame within <paramref name="timeout"/>; <see cref="Frame"/> then holds it.</summary>
    /// <param name="expectStart">True where a frame starts with <c>@</c> (noise before it is skipped).</param>
    /// <param name="timeout">The frame's deadline from now.</param>
    /// <returns>The frame's length, CR included.</returns>
    /// <exception cref="HostLinkTimeoutException">No frame within the deadline.</exception>
    /// <exception cref="HostLinkFrameException">More than <see cref="FrameReader.MaxFrameLength"/> characters arrived without a CR.</exception>
    /// <exception cref="HostLinkConnectionException">The stream ended or failed.</exception>
    /// <exception cref="OperationCanceledException">The caller cancelled.</exception>
    public ValueTask<int> ReadFrameAsync(bool expectStart, TimeSpan timeout)
        => TakeAsync(expectStart, ReadOnlyMemory<byte>.Empty, timeout);

    /// <summary>Reads back our own transmission from a line that echoes it, and checks it.</summary>
    /// <exception cref="HostLinkTimeoutException">The echo did not come within its deadline.</exception>
    /// <exception cref="HostLinkFrameException">The echo differs from what was sent.</exception>
    /// <returns>The length of the echo.</returns>
    public ValueTask<int> ReadEchoAsync(ReadOnlyMemory<byte> sent, TimeSpan timeout)
        => TakeAsync(expectStart: false, sent, timeout);

    /// <summary>Throws away everything received and not yet read; the frames that start in it settle owed answers.</summary>
    /// <returns>The number of bytes discarded.</returns>
    public int Discard(AnswerTiming? settle = null)
    {
        int discarded;
        bool resume;
        lock (_lock)
        {
            settle?.SettledAll(_received.HeldBytes);
            discarded = _received.Clear();
            resume = ConsumedLocked();
        }

        ResumeReading(resume);
        return discarded;
    }

    /// <summary>Asks the receive loop to stop; a read still pending ends when the stream is closed or honours the request.</summary>
    public void RequestStop()
    {
        _stopReading.Cancel();
        lock (_lock)
        {
            _closed = true;
            if (!_reading)
            {
                _readingStopped.TrySetResult(true);
            }
        }
    }

    /// <summary>Waits until the receive loop has stopped (after <see cref="RequestStop"/> and closing the stream), and lets go of the timer.</summary>
    public async ValueTask WaitStoppedAsync()
    {
        await _readingStopped.Task.ConfigureAwait(false);
        lock (_lock)
        {
            _stopped = true;
            _deadline.Dispose();
            _writeAbort.Dispose();
        }
    }

    bool IValueTaskSource<bool>.GetResult(short token) => _waiter.GetResult(token);

    ValueTaskSourceStatus IValueTaskSource<bool>.GetStatus(short token) => _waiter.GetStatus(token);

    void IValueTaskSource<bool>.OnCompleted(Action<object?> continuation, object? state, short token, ValueTaskSourceOnCompletedFlags flags)
        => _waiter.OnCompleted(continuation, state, token, flags);

    /// <summary>
    /// Waits until the buffer holds what the caller wants: a frame, or (with <paramref name="echo"/>) the echo of what
    /// was sent; else the deadline, the caller's token or the end of the stream ends the wait.
    /// </summary>
    /// <returns>The length taken: a frame's (then in <see cref="Frame"/>) or the echo's.</returns>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    private async ValueTask<int> TakeAsync(bool expectStart, ReadOnlyMemory<byte> echo, TimeSpan timeout)
    {
        ArmDeadline(timeout);
        while (true)
        {
            int taken;
            bool resume;
            Exception? error;
            lock (_lock)
            {
                ThrowIfAbortedLocked();
                ThrowIfCancelledLocked();
                // Bytes that came after the deadline are left in the buffer: the resynchronisation that follows a timeout
                // discards them and settles what they answer.
                bool late = ArrivedAfterDeadlineLocked();
                taken = 0;
                error = null;
                if (!late)
                {
                    taken = echo.IsEmpty ? _received.TakeFrame(expectStart, _frame, out error) : _received.TakeEcho(echo.Span, out error);
                    FrameArrivedAt = _receivedAt;
                }

                if (taken == 0 && error is null)
                {
                    if (_deadlinePassed || late)
                    {
                        error = new HostLinkTimeoutException(
                            echo.IsEmpty ? $"No answer from {_description} within {timeout.TotalMilliseconds:0} ms." : $"The line did not echo our frame (LocalEcho is on) within {timeout.TotalMilliseconds:0} ms.",
                            timeout);
                    }
                    else if (_closed)
                    {
                        error = _closedReason is { } reason
                            ? new HostLinkConnectionException(reason.Message, reason.InnerException)
                            : new HostLinkConnectionException($"{_description} closed the connection in the middle of an exchange.");
                    }
                    else
                    {
                        _waiter.Reset();
                        _waiting = true;
                    }
                }

                resume = ConsumedLocked();
            }

            ResumeReading(resume);
            if (error is not null)
            {
                throw error;
            }

            if (taken > 0)
            {
                if (echo.IsEmpty)
                {
                    Observe(taken);
                }

                return taken;
            }

            await new ValueTask<bool>(this, _waiter.Version).ConfigureAwait(false);
        }
    }

    /// <summary>
    /// Whether bytes arrived after the frame's deadline by the link's clock. A frame is judged by when its bytes came,
    /// not by when the deadline's timer callback ran: on a busy host the callback can run after bytes that came later,
    /// and an answer after the deadline is a timeout however soon the link gets to it.
    /// </summary>
    private bool ArrivedAfterDeadlineLocked()
        => _deadlineTimeout >= TimeSpan.Zero && _receivedAt > _deadlineArmedAt && _time.GetElapsedTime(_deadlineArmedAt, _receivedAt) > _deadlineTimeout;

    private void ArmDeadline(TimeSpan timeout)
    {
        lock (_lock)
        {
            _deadlinePassed = false;
            _deadlineArmedAt = _time.GetTimestamp();
            _deadlineTimeout = timeout;
        }

        _deadline.Change(timeout, Timeout.InfiniteTimeSpan);
    }

    private void ThrowIfAbortedLocked()
    {
        if (_abortReason is { } reason)
        {
            throw new HostLinkConnectionException(reason.Message, reason.InnerException);
        }
    }

    private void ThrowIfCancelledLocked()
    {
        if (_cancelled)
        {
            throw new OperationCanceledException(_callerToken);
        }
    }

    private void OnDeadline()
    {
        bool wake;
        lock (_lock)
        {
            if (_deadlineTimeout == Timeout.InfiniteTimeSpan)
            {
                return;
            }

            // Early (timer granularity) or left over from the previous frame's arming: wait for what is left.
            TimeSpan left = _deadlineTimeout - _time.GetElapsedTime(_deadlineArmedAt);
            if (left > TimeSpan.Zero)
            {
                _deadline.Change(left, Timeout.InfiniteTimeSpan);
                return;
            }

            _deadlinePassed = true;
            CancelWritesLocked();
            wake = TakeWaiterLocked();
        }

        Wake(wake);
    }

    private void OnCallerCancelled()
    {
        bool wake;
        lock (_lock)
        {
            _cancelled = true;
            CancelWritesLocked();
            wake = TakeWaiterLocked();
        }

        Wake(wake);
    }

    private void CancelWritesLocked()
    {
        try
        {
            _writeAbort.Cancel();
        }
        catch (ObjectDisposedException)
        {
        }
    }

    private bool TakeWaiterLocked()
    {
        if (!_waiting)
        {
            return false;
        }

        _waiting = false;
        return true;
    }

    private void Wake(bool wake)
    {
        if (wake)
        {
            _waiter.SetResult(true);
        }
    }

    /// <summary>After bytes were taken: whether a paused receive loop should read again.</summary>
    private bool ConsumedLocked()
    {
        if (!_reading && !_closed && _received.Held < ResumeThreshold)
        {
            _reading = true;
            return true;
        }

        return false;
    }

    private void ResumeReading(bool resume)
    {
        if (resume)
        {
            ReadLoop();
        }
    }

    /// <summary>Issues reads until one is pending (its completion continues the loop), the buffer is full, or the stream ends.</summary>
    private void ReadLoop()
    {
        bool wake = false;
        try
        {
            while (true)
            {
                ValueTask<int> read;
                try
                {
                    read = StreamCompat.ReadAsync(_stream, _readBuffer, _stopReading.Token);
                }
                catch (Exception e)
                {
                    wake |= Closed(e);
                    return;
                }

                // Without the caller's synchronization context: the loop must never wait for a test runner's or UI thread.
                ConfiguredValueTaskAwaitable<int>.ConfiguredValueTaskAwaiter awaiter = read.ConfigureAwait(false).GetAwaiter();
                if (!awaiter.IsCompleted)
                {
                    _pendingRead = awaiter;
                    awaiter.UnsafeOnCompleted(_onReadCompleted);
                    return;
                }

                if (!Deliver(awaiter, ref wake))
                {
                    return;
                }
            }
        }
        finally
        {
            Wake(wake);
        }
    }

    private void OnReadCompleted()
    {
        ConfiguredValueTaskAwaitable<int>.ConfiguredValueTaskAwaiter completed = _pendingRead;
        _pendingRead = default;
        bool wake = false;
        bool more = Deliver(completed, ref wake);

        // The next read is pending before the frame reader resumes on this thread.
        if (more)
        {
            ReadLoop();
        }

        Wake(wake);
    }

    /// <summary>Takes a completed read's bytes into the buffer.</summary>
    /// <returns>Whether the loop should read again.</returns>
    private bool Deliver(ConfiguredValueTaskAwaitable<int>.ConfiguredValueTaskAwaiter completed, ref bool wake)
    {
        int n;
        try
        {
            n = completed.GetResult();
        }
        catch (Exception e)
        {
            wake |= Closed(e);
            return false;
        }

        if (n == 0)
        {
            wake |= Closed(new HostLinkConnectionException($"{_description} closed the connection."));
            return false;
        }

        long now = _time.GetTimestamp();
        lock (_lock)
        {
            _received.Append(_readBuffer.AsSpan(0, n));
            _receivedAt = now;
            wake |= TakeWaiterLocked();
            if (_stopReading.IsCancellationRequested || _received.Held >= PauseThreshold)
            {
                // Held back until a reader drains the buffer (or for good, when stopping).
                _reading = false;
                if (_stopReading.IsCancellationRequested)
                {
                    _readingStopped.TrySetResult(true);
                }

                return false;
            }
        }

        return true;
    }

    private bool Closed(Exception e)
    {
        lock (_lock)
        {
            if (!_stopReading.IsCancellationRequested && !_closed)
            {
                _closedReason = e as HostLinkConnectionException ?? new HostLinkConnectionException($"Lost {_description}: {e.Message}", e);
            }

            _closed = true;
            _reading = false;
            _readingStopped.TrySetResult(true);
            return TakeWaiterLocked();
        }
    }

    private void Observe(int length)
    {
        Tap?.OnFrame(new TappedFrame(LineDirection.FromPlc, _time.GetUtcNow(), _frame.AsSpan(0, length), _tapUnit, _tapHeader));
        if (_logger.IsEnabled(LogLevel.Trace))
        {
            HostLinkLog.Frame(_logger, _description, "<<", FrameText.Printable(_frame.AsSpan(0, length)));
        }
    }
}
