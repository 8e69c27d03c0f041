using System.Buffers;
using System.Diagnostics;
using System.IO.Pipelines;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Logging.Abstractions;
using OmronHostLink.Protocol;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The one owner of the wire. Carries one transaction at a time over the transport's stream: frames the command
/// (with the CR handshake between command frames), receives and validates every response frame (asking for the next
/// with a bare CR), enforces per-frame deadlines, and resynchronises after any failure so that a late answer to an
/// old request can never be taken for the answer to a new one.
/// </summary>
/// <remarks>
/// A background pump copies everything the stream delivers into a bounded pipe; transactions read frames from the
/// pipe. The stream read itself is never cancelled, so no transport has to support cancelling a pending read, and
/// bytes that arrive between transactions are kept until resynchronisation discards them.
/// <para>
/// Resynchronisation: after a timeout, cancellation, damaged frame or lost handshake, the next transaction first
/// (1) sends <c>@**</c> (INITIALIZE) if a multi-frame exchange was cut, (2) discards what is buffered, and (3) sends a
/// TS (TEST) fence with a random token to the unit that failed, discarding every frame until that token is echoed.
/// A PLC answers in order, so any late answer to the old request arrives before the echo and is thrown away.
/// </para>
/// </remarks>
internal sealed class HostLinkConnection : IAsyncDisposable
{
    private const int MaxFirstFrame = FrameWriter.MaxFirstFrameLength;
    private const int MaxContinuationFrame = FrameWriter.MaxContinuationFrameLength;

    private static readonly Random TokenRandom = new();

    private readonly IHostLinkTransport _transport;
    private readonly HostLinkConnectionOptions _options;
    private readonly ILogger _logger;
    private readonly SemaphoreSlim _gate = new(1, 1);
    private readonly byte[] _frame = new byte[FrameReader.MaxFrameLength + 2];
    private readonly byte[] _tx = new byte[FrameReader.MaxFrameLength + 8];
    private byte[] _text = new byte[256];
    private int _textLength;

    private Stream? _stream;
    private Pipe? _pipe;
    private Task? _pump;
    private CancellationTokenSource? _pumpStop;
    private bool _needsResync;
    private int _resyncUnit;
    private bool _midExchange;
    private bool _disposed;
    private int _sid;

    public HostLinkConnection(IHostLinkTransport transport, HostLinkConnectionOptions options)
    {
        _transport = transport;
        _options = options;
        Timing = transport.LineTiming ?? options.LineTiming;
        _logger = options.LoggerFactory?.CreateLogger("OmronHostLink") ?? NullLogger.Instance;
    }

    /// <summary>The timing every deadline is computed from.</summary>
    public LineTiming Timing { get; }

    public string Description => _transport.Description;

    /// <summary>The next FINS service ID: every FINS exchange carries its own, so an answer to another one is refused.</summary>
    public byte NextSid() => unchecked((byte)Interlocked.Increment(ref _sid));

    /// <summary>Observes every frame sent and received (for the console's --verbose).</summary>
    public Action<bool, ReadOnlyMemory<byte>>? FrameObserver { get; set; }

    /// <summary>
    /// The deadline for a frame: the characters still to cross the line (what we sent and the longest answer) at the
    /// line's character rate, plus the PLC's turnaround allowance.
    /// </summary>
    public TimeSpan FrameTimeout(int charactersSent, int charactersExpected)
        => Timing.WireTime(charactersSent + charactersExpected) + _options.TurnaroundAllowance;

    /// <summary>Runs one request, with retries where allowed.</summary>
    public async ValueTask<TResult> ExecuteAsync<TState, TResult>(HostLinkRequest request, int retries, ResponseDecoder<TState, TResult> decode, TState state, CancellationToken cancellationToken)
    {
        if (!request.MultiFrame && !request.SingleFrameOnly && request.Message.Length + FrameWriter.FinalOverhead > MaxFirstFrame)
        {
            throw new ArgumentException($"The {request.Header} command is {request.Message.Length + FrameWriter.FinalOverhead} characters long; it must fit one {MaxFirstFrame}-character frame.");
        }

        int attempt = 0;
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
            try
            {
                ObjectDisposedExceptionThrowIf();
                await EnsureOpenAsync(cancellationToken).ConfigureAwait(false);
                if (_needsResync)
                {
                    await ResyncAsync(request.Unit, cancellationToken).ConfigureAwait(false);
                }

                return await AttemptAsync(request, decode, state, cancellationToken).ConfigureAwait(false);
            }
            catch (Exception e) when (attempt < retries && request.Retryable && IsRetryable(e) && !cancellationToken.IsCancellationRequested)
            {
                attempt++;
                HostLinkMetrics.Retry(request.Header);
                HostLinkLog.Retry(_logger, request.Unit, request.Header, e.Message, attempt, retries);
            }
            finally
            {
                _gate.Release();
            }
        }
    }

    /// <summary>Sends a bare transmission with no answer (<c>@**</c>).</summary>
    public async ValueTask SendRawAsync(ReadOnlyMemory<byte> bytes, CancellationToken cancellationToken)
    {
        await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            ObjectDisposedExceptionThrowIf();
            await EnsureOpenAsync(cancellationToken).ConfigureAwait(false);
            await WriteAsync(bytes, cancellationToken).ConfigureAwait(false);
            _midExchange = false;
        }
        finally
        {
            _gate.Release();
        }
    }

    public async ValueTask DisposeAsync()
    {
        if (_disposed)
        {
            return;
        }

        await _gate.WaitAsync().ConfigureAwait(false);
        try
        {
            _disposed = true;
            await DropAsync(null).ConfigureAwait(false);
            await _transport.DisposeAsync().ConfigureAwait(false);
        }
        finally
        {
            _gate.Release();
        }
    }

    private static bool IsRetryable(Exception e) => e switch
    {
        HostLinkTimeoutException => true,
        HostLinkFrameException => true,
        HostLinkEndCodeException ec => ec.Category == EndCodeCategory.FrameDamaged,
        _ => false,
    };

    private void ObjectDisposedExceptionThrowIf()
    {
        if (_disposed)
        {
            throw new ObjectDisposedException(nameof(HostLinkConnection), $"The link to {_transport.Description} is closed.");
        }
    }

    private async ValueTask<TResult> AttemptAsync<TState, TResult>(HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state, CancellationToken cancellationToken)
    {
        long started = Stopwatch.GetTimestamp();
        using var deadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        int frames = 0;
        try
        {
            // Send: frame by frame; between command frames the PLC answers a bare CR (or an error at once).
            int offset = 0;
            int sentChars = 0;
            bool first = true;
            bool final;
            int preRead = 0;
            do
            {
                int remaining = request.Message.Length - offset;
                int length;
                if (request.SingleFrameOnly)
                {
                    length = remaining;
                    final = true;
                }
                else
                {
                    length = FrameWriter.NextSegmentLength(remaining, first, request.FixedLength, request.AtomLength, out final);
                }

                int frameLength = FrameWriter.WriteFrame(request.Message.Span.Slice(offset, length), final, _tx);
                _midExchange = !final;
                await WriteAsync(_tx.AsMemory(0, frameLength), deadline.Token).ConfigureAwait(false);
                sentChars = frameLength;
                frames++;
                if (_options.LocalEcho)
                {
                    await ConsumeEchoAsync(frameLength, deadline, cancellationToken).ConfigureAwait(false);
                }

                offset += length;
                first = false;
                if (!final)
                {
                    int n = await ReadFrameAsync(expectStart: false, FrameTimeout(frameLength, 1), deadline, cancellationToken).ConfigureAwait(false);
                    int at = Array.IndexOf(_frame, (byte)'@', 0, n);
                    if (at >= 0)
                    {
                        // The PLC answered before the last frame: an error for what it has seen so far.
                        Buffer.BlockCopy(_frame, at, _frame, 0, n - at);
                        preRead = n - at;
                        _midExchange = false;
                        break;
                    }
                }
            }
            while (!final);

            if (!request.ExpectsResponse)
            {
                _midExchange = false;
                Completed(request, started, frames);
                return decode(ReadOnlySpan<byte>.Empty, state);
            }

            // Receive: the first frame, then each continuation after our bare CR.
            _textLength = 0;
            int firstExpected = request.SingleFrameOnly
                ? CModeOverhead + request.MaxResponseText
                : Math.Min(MaxFirstFrame, CModeOverhead + request.MaxResponseText);
            // An answer that may span frames is cut if its first frame is lost or damaged: the PLC then holds the rest
            // and takes any command, our TS fence included, as the delimiter asking for it. Only INITIALIZE ends that,
            // so resynchronisation must send @** then too (the soak found fences answered with stale continuation frames).
            _midExchange = preRead == 0 && !request.SingleFrameOnly && CModeOverhead + request.MaxResponseText > MaxFirstFrame;
            TimeSpan firstTimeout = FrameTimeout(sentChars, firstExpected);
            int len = preRead > 0
                ? preRead
                : await ReadFrameAsync(expectStart: true, firstTimeout, deadline, cancellationToken).ConfigureAwait(false);
            if (preRead == 0 && IsOwnEcho(request, len, sentChars))
            {
                // A line that echoes (2-wire RS-485) with LocalEcho off: our own frame is not the answer.
                len = await ReadFrameAsync(expectStart: true, firstTimeout, deadline, cancellationToken).ConfigureAwait(false);
            }

            FrameInfo info = FrameParser.ParseFirst(_frame.AsSpan(0, len));
            _midExchange = !info.IsFinal;
            CheckEcho(request, info);
            AppendText(info.Text(_frame.AsSpan(0, len)), request);
            frames++;
            while (!info.IsFinal)
            {
                _midExchange = true;
                await WriteAsync(DelimiterBytes, deadline.Token).ConfigureAwait(false);
                if (_options.LocalEcho)
                {
                    await ConsumeEchoAsync(1, deadline, cancellationToken).ConfigureAwait(false);
                }

                len = await ReadFrameAsync(expectStart: false, FrameTimeout(1, MaxContinuationFrame), deadline, cancellationToken).ConfigureAwait(false);
                info = FrameParser.ParseContinuation(_frame.AsSpan(0, len));
                AppendText(info.Text(_frame.AsSpan(0, len)), request);
                frames++;
            }

            _midExchange = false;
            TResult result = decode(_text.AsSpan(0, _textLength), state);
            Completed(request, started, frames);
            return result;
        }
        catch (HostLinkEndCodeException e) when (!_midExchange)
        {
            // A complete error answer: the link is still in step.
            HostLinkMetrics.Completed(request.Header, Elapsed(started));
            HostLinkMetrics.Error(request.Header, "end_code", e.EndCode.ToCode());
            HostLinkLog.Failed(_logger, request.Unit, request.Header, e.Message);
            throw;
        }
        catch (FinsEndCodeException e) when (!_midExchange)
        {
            HostLinkMetrics.Completed(request.Header, Elapsed(started));
            HostLinkMetrics.Error(request.Header, "fins_end_code", e.EndCode.ToString());
            HostLinkLog.Failed(_logger, request.Unit, request.Header, e.Message);
            throw;
        }
        catch (HostLinkConnectionException e)
        {
            HostLinkMetrics.Error(request.Header, "connection", null);
            HostLinkLog.Lost(_logger, _transport.Description, e.Message);
            await DropAsync(e).ConfigureAwait(false);
            throw;
        }
        catch (Exception e)
        {
            _needsResync = true;
            _resyncUnit = request.Unit;
            HostLinkMetrics.Error(request.Header, e switch
            {
                HostLinkTimeoutException => "timeout",
                HostLinkFrameException => "frame",
                OperationCanceledException => "cancelled",
                _ => "other",
            }, null);
            HostLinkLog.Failed(_logger, request.Unit, request.Header, e.Message);
            throw;
        }
    }

    /// <summary><c>@</c>, unit, header, FCS, <c>*</c>, CR around the response text.</summary>
    private const int CModeOverhead = 9;

    private static ReadOnlyMemory<byte> DelimiterBytes { get; } = new byte[] { (byte)'\r' };

    private static double Elapsed(long started) => (Stopwatch.GetTimestamp() - started) * 1000.0 / Stopwatch.Frequency;

    private void Completed(HostLinkRequest request, long started, int frames)
    {
        double ms = Elapsed(started);
        HostLinkMetrics.Completed(request.Header, ms);
        HostLinkLog.Transaction(_logger, request.Unit, request.Header, ms, frames);
    }

    /// <summary>
    /// Whether the frame just read is our own last frame coming back. Only where no correct answer can equal the
    /// command: a TS answer is the command, and a two-character text (SC 00, MF 01) reads as a bare end code.
    /// </summary>
    private bool IsOwnEcho(HostLinkRequest request, int length, int sentLength)
        => !_options.LocalEcho
            && request.Header != "TS"
            && request.Message.Length - 5 != 2
            && length == sentLength
            && _frame.AsSpan(0, length).SequenceEqual(_tx.AsSpan(0, sentLength));

    private void CheckEcho(HostLinkRequest request, FrameInfo info)
    {
        ReadOnlySpan<byte> header = _frame.AsSpan(3, 2);
        if (info.Unit != request.Unit)
        {
            throw new HostLinkFrameException(FrameError.WrongUnit, $"Unit {info.Unit:D2} answered a command sent to unit {request.Unit:D2}.", _frame.AsSpan(0, Math.Min(_frame.Length, 16)));
        }

        if (header[0] == (byte)'I' && header[1] == (byte)'C' && request.Header != "IC")
        {
            if (!info.IsFinal || info.TextLength != 0)
            {
                throw new HostLinkFrameException(FrameError.Malformed, "An IC answer carries no text.");
            }

            throw new HostLinkEndCodeException(EndCode.UndefinedHeader, request.Header, request.Unit);
        }

        if (header[0] != (byte)request.Header[0] || header[1] != (byte)request.Header[1])
        {
            throw new HostLinkFrameException(FrameError.WrongHeader, $"The answer's header {FrameText.Printable(header)} does not echo the command's {request.Header}.");
        }
    }

    private void AppendText(ReadOnlySpan<byte> text, HostLinkRequest request)
    {
        if (_textLength + text.Length > request.MaxResponseText)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The answer to {request.Header} is longer than the {request.MaxResponseText} characters it can hold.");
        }

        if (_textLength + text.Length > _text.Length)
        {
            Array.Resize(ref _text, Math.Max(_text.Length * 2, _textLength + text.Length));
        }

        text.CopyTo(_text.AsSpan(_textLength));
        _textLength += text.Length;
    }

    private async ValueTask EnsureOpenAsync(CancellationToken cancellationToken)
    {
        if (_pipe is not null)
        {
            return;
        }

        Stream stream = await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        var pipe = new Pipe(new PipeOptions(pauseWriterThreshold: 64 * 1024, resumeWriterThreshold: 32 * 1024, useSynchronizationContext: false));
        _pumpStop = new CancellationTokenSource();
        _stream = stream;
        _pipe = pipe;
        _needsResync = false;
        _midExchange = false;
        _pump = Task.Run(() => PumpAsync(stream, pipe.Writer, _pumpStop.Token));
        HostLinkLog.Opened(_logger, _transport.Description);
    }

    private async Task PumpAsync(Stream stream, PipeWriter writer, CancellationToken stop)
    {
        Exception? error = null;
        try
        {
            while (true)
            {
                Memory<byte> memory = writer.GetMemory(512);
                int n = await StreamCompat.ReadAsync(stream, memory, stop).ConfigureAwait(false);
                if (n == 0)
                {
                    error = new HostLinkConnectionException($"{_transport.Description} closed the connection.");
                    break;
                }

                writer.Advance(n);
                FlushResult flushed = await writer.FlushAsync(stop).ConfigureAwait(false);
                if (flushed.IsCompleted)
                {
                    break;
                }
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or OperationCanceledException or System.Net.Sockets.SocketException or InvalidOperationException)
        {
            error = new HostLinkConnectionException($"Lost {_transport.Description}: {e.Message}", e);
        }

        await writer.CompleteAsync(error).ConfigureAwait(false);
    }

    private async ValueTask DropAsync(Exception? reason)
    {
        _pumpStop?.Cancel();
        if (_pipe is not null)
        {
            await _pipe.Reader.CompleteAsync().ConfigureAwait(false);
        }

        _pipe = null;
        _stream = null;
        _needsResync = false;
        _midExchange = false;
        try
        {
            await _transport.CloseAsync().ConfigureAwait(false);
        }
        catch (Exception e) when (reason is not null && e is IOException or ObjectDisposedException)
        {
        }

        if (_pump is not null)
        {
            try
            {
                await _pump.ConfigureAwait(false);
            }
            catch (Exception e) when (e is OperationCanceledException or IOException or ObjectDisposedException)
            {
            }
        }

        _pump = null;
        _pumpStop?.Dispose();
        _pumpStop = null;
    }

    private async ValueTask WriteAsync(ReadOnlyMemory<byte> bytes, CancellationToken cancellationToken)
    {
        Stream stream = _stream ?? throw new HostLinkConnectionException($"{_transport.Description} is not open.");
        FrameObserver?.Invoke(true, bytes);
        if (_logger.IsEnabled(LogLevel.Trace))
        {
            HostLinkLog.Frame(_logger, _transport.Description, ">>", FrameText.Printable(bytes.Span));
        }

        try
        {
            await StreamCompat.WriteAsync(stream, bytes, cancellationToken).ConfigureAwait(false);
            await stream.FlushAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or System.Net.Sockets.SocketException or InvalidOperationException)
        {
            throw new HostLinkConnectionException($"Lost {_transport.Description} while sending: {e.Message}", e);
        }
    }

    /// <summary>Waits for the next CR-terminated frame and copies it into <see cref="_frame"/>.</summary>
    /// <returns>The frame's length, CR included.</returns>
    private async ValueTask<int> ReadFrameAsync(bool expectStart, TimeSpan timeout, CancellationTokenSource deadline, CancellationToken callerToken)
    {
        PipeReader reader = _pipe!.Reader;
        deadline.CancelAfter(timeout);
        while (true)
        {
            ReadResult result = await ReadWithinAsync(reader, timeout, deadline, callerToken, "No answer from " + _transport.Description).ConfigureAwait(false);

            ReadOnlySequence<byte> buffer = result.Buffer;
            FrameScanResult scan = FrameReader.TryReadFrame(ref buffer, expectStart, out ReadOnlySequence<byte> frame, out _);
            if (scan == FrameScanResult.Frame)
            {
                int length = (int)frame.Length;
                frame.CopyTo(_frame);
                reader.AdvanceTo(buffer.Start);
                Observe(false, length);
                return length;
            }

            if (scan == FrameScanResult.Overflow)
            {
                reader.AdvanceTo(buffer.End);
                throw new HostLinkFrameException(FrameError.TooLong, $"More than {FrameReader.MaxFrameLength} characters arrived without a CR.");
            }

            reader.AdvanceTo(buffer.Start, buffer.End);
            if (result.IsCompleted)
            {
                throw new HostLinkConnectionException($"{_transport.Description} closed the connection in the middle of an answer.");
            }
        }
    }

    private void Observe(bool sent, int length)
    {
        FrameObserver?.Invoke(sent, _frame.AsMemory(0, length).ToArray());
        if (_logger.IsEnabled(LogLevel.Trace))
        {
            HostLinkLog.Frame(_logger, _transport.Description, sent ? ">>" : "<<", FrameText.Printable(_frame.AsSpan(0, length)));
        }
    }

    /// <summary>One read from the pipe that turns the deadline's cancellation into a timeout (the caller's own cancellation stays a cancellation).</summary>
    private static async ValueTask<ReadResult> ReadWithinAsync(PipeReader reader, TimeSpan timeout, CancellationTokenSource deadline, CancellationToken callerToken, string what)
    {
        try
        {
            return await reader.ReadAsync(deadline.Token).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (!callerToken.IsCancellationRequested && deadline.IsCancellationRequested)
        {
            throw new HostLinkTimeoutException($"{what} within {timeout.TotalMilliseconds:0} ms.", timeout);
        }
    }

    /// <summary>Reads back our own transmission from a line that echoes it, and checks it.</summary>
    private async ValueTask ConsumeEchoAsync(int length, CancellationTokenSource deadline, CancellationToken callerToken)
    {
        PipeReader reader = _pipe!.Reader;
        TimeSpan timeout = FrameTimeout(length, 0);
        deadline.CancelAfter(timeout);
        while (true)
        {
            ReadResult result = await ReadWithinAsync(reader, timeout, deadline, callerToken, "The line did not echo our frame (LocalEcho is on)").ConfigureAwait(false);

            ReadOnlySequence<byte> buffer = result.Buffer;
            if (buffer.Length >= length)
            {
                ReadOnlySequence<byte> echo = buffer.Slice(0, length);
                bool same = echo.IsSingleSegment ? echo.First.Span.SequenceEqual(_tx.AsSpan(0, length)) : echo.ToArray().AsSpan().SequenceEqual(_tx.AsSpan(0, length));
                reader.AdvanceTo(echo.End);
                if (!same)
                {
                    throw new HostLinkFrameException(FrameError.Unexpected, "The line's echo of our frame differs from what was sent.");
                }

                return;
            }

            reader.AdvanceTo(buffer.Start, buffer.End);
            if (result.IsCompleted)
            {
                throw new HostLinkConnectionException($"{_transport.Description} closed the connection.");
            }
        }
    }

    /// <summary>How many TS fences a resynchronisation tries before the exchange fails.</summary>
    private const int FenceAttempts = 2;

    /// <summary>Writes a TS fence frame with a fresh random token into <see cref="_tx"/>.</summary>
    /// <returns>The frame's length.</returns>
    private int WriteFenceFrame(int unit)
    {
        Span<byte> message = stackalloc byte[Protocol.CMode.CModeCommand.PrefixLength + 8];
        message[0] = (byte)'@';
        HexAscii.WriteDecimal(unit, message.Slice(1, 2));
        message[3] = (byte)'T';
        message[4] = (byte)'S';
        lock (TokenRandom)
        {
            for (int i = 5; i < message.Length; i++)
            {
                message[i] = HexAscii.Nibble(TokenRandom.Next(16));
            }
        }

        return FrameWriter.WriteFrame(message, final: true, _tx);
    }

    private async ValueTask ResyncAsync(int requestUnit, CancellationToken cancellationToken)
    {
        long discarded = 0;
        int unit = _resyncUnit;
        PipeReader reader = _pipe!.Reader;
        using var deadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        if (_midExchange)
        {
            // A multi-frame exchange was cut: INITIALIZE resets every unit's transmission control.
            await WriteAsync(Protocol.CMode.CModeFrames.Initialize.ToArray(), deadline.Token).ConfigureAwait(false);
            _midExchange = false;
        }

        if (reader.TryRead(out ReadResult pending))
        {
            discarded += pending.Buffer.Length;
            reader.AdvanceTo(pending.Buffer.End);
        }

        // The fence: TS with a token nobody else can have sent. A fence answer can itself be hit by line damage, so a
        // second fence is tried before the exchange is given up; it goes to the unit the caller wants, since a unit that
        // did not echo a fresh TS within its deadline is not talking.
        string outcome = "unanswered";
        TimeSpan timeout = TimeSpan.Zero;
        for (int attempt = 0; attempt < FenceAttempts && outcome != "answered"; attempt++)
        {
            // Each fence has a deadline of its own: the previous one's has fired.
            using var fenceDeadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
            int target = attempt == 0 ? unit : requestUnit;
            int frameLength = WriteFenceFrame(target);
            await WriteAsync(_tx.AsMemory(0, frameLength), fenceDeadline.Token).ConfigureAwait(false);
            if (_options.LocalEcho)
            {
                await ConsumeEchoAsync(frameLength, fenceDeadline, cancellationToken).ConfigureAwait(false);
            }

            timeout = FrameTimeout(frameLength, frameLength);
            var clock = Stopwatch.StartNew();
            while (clock.Elapsed < timeout)
            {
                TimeSpan left = timeout - clock.Elapsed;
                int n;
                try
                {
                    n = await ReadFrameAsync(expectStart: true, left > TimeSpan.FromMilliseconds(1) ? left : TimeSpan.FromMilliseconds(1), fenceDeadline, cancellationToken).ConfigureAwait(false);
                }
                catch (HostLinkTimeoutException)
                {
                    break;
                }
                catch (HostLinkFrameException)
                {
                    // Damaged leftovers of the failed exchange: discarded like any other stale bytes.
                    outcome = "unanswered after damaged frames";
                    continue;
                }

                if (n == frameLength && _frame.AsSpan(0, n).SequenceEqual(_tx.AsSpan(0, frameLength)))
                {
                    outcome = "answered";
                    break;
                }

                discarded += n;
            }
        }

        HostLinkLog.Resync(_logger, unit, discarded, outcome);
        if (outcome == "answered")
        {
            _needsResync = false;
            return;
        }

        // Not in step yet: this exchange fails and the next one fences again, at the unit it wants.
        _resyncUnit = requestUnit;
        throw new HostLinkTimeoutException(
            $"No answer from unit {requestUnit:D2} on {_transport.Description} within {timeout.TotalMilliseconds:0} ms (it did not echo the TS check sent to resynchronise the link after a failed exchange).",
            timeout);
    }
}
