using System.Runtime.CompilerServices;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// One attempt at one exchange over a <see cref="FrameChannel"/>: the command frame by frame (with the PLC's CR between
/// command frames), then the answer frame by frame (asking for each next one with a bare CR), every frame checked, the
/// text joined and decoded. Keeps, step by step, the <see cref="LinkState"/> the line is left in if the exchange stops
/// there, so that a failed attempt yields the link's next state: <see cref="After"/>. One instance per connection,
/// reused: an attempt allocates nothing of its own.
/// </summary>
internal sealed class TransactionAttempt
{
    private static readonly ReadOnlyMemory<byte> Delimiter = new byte[] { (byte)'\r' };

    private readonly LineTiming _timing;
    private readonly TimeProvider _time;
    private readonly TimeSpan _turnaround;
    private readonly bool _localEcho;
    private readonly AnswerTiming _answerTiming;
    private readonly Resynchroniser _resynchroniser;
    private readonly byte[] _tx = new byte[FrameReader.MaxFrameLength + 8];
    private byte[] _text = new byte[256];
    private int _textLength;

    // The first answer's text of a read carried twice to be confirmed.
    private byte[] _confirmed = Array.Empty<byte>();

    // The start of the last write (a command frame or the CR asking for the next answer frame) and its length: no answer
    // frame can be complete before both have crossed the line.
    private long _sentAt;
    private int _sentChars;

    // Why the answer's one frame looks too early to be this command's, or null: put to a TS check before it is taken.
    private string? _early;

    // The state the line is left in if the exchange stops now: NeedsInitialize inside a multi-frame exchange (the PLC
    // holds the rest of a command or an answer), Ready once the whole answer is in, NeedsResync otherwise.
    private LinkState _ifStopped;

    public TransactionAttempt(LineTiming timing, TimeSpan turnaround, bool localEcho, TimeProvider time, AnswerTiming answerTiming, Resynchroniser resynchroniser)
    {
        _timing = timing;
        _time = time;
        _turnaround = turnaround;
        _localEcho = localEcho;
        _answerTiming = answerTiming;
        _resynchroniser = resynchroniser;
    }

    /// <summary>The framing of a Serial Communications Unit's Host Link-compatible mode, each answer frame checked against it; null for any.</summary>
    public CompatibleModeFraming? AnswerFraming { get; init; }

    /// <summary>Whether every C-mode answer is verified by a TS check behind it (<see cref="HostLinkClientOptions.VerifyAnswers"/>).</summary>
    public bool VerifyAnswers { get; init; }

    /// <summary>Command frames sent by the last attempt (not the bare CRs between frames).</summary>
    public int FramesSent { get; private set; }

    /// <summary>Answer frames received by the last attempt, damaged ones included (not the bare CRs between frames).</summary>
    public int FramesReceived { get; private set; }

    /// <summary>When the last attempt sent its first frame (the link's clock); 0 when no attempt ran since <see cref="Reset"/>.</summary>
    public long StartedAt { get; private set; }

    /// <summary>Frames sent and received by the last attempt.</summary>
    public int Frames => FramesSent + FramesReceived;

    /// <summary>Forgets the last attempt, before a transaction that may fail before an attempt starts (or runs none).</summary>
    public void Reset()
    {
        FramesSent = 0;
        FramesReceived = 0;
        StartedAt = 0;
        _ifStopped = LinkState.NeedsResync;
    }

    /// <summary>The deadline for a frame: <see cref="LineTiming.FrameDeadline"/> with the link's turnaround allowance.</summary>
    private TimeSpan FrameTimeout(int charactersSent, int charactersExpected)
        => _timing.FrameDeadline(charactersSent, charactersExpected, _turnaround);

    /// <summary>
    /// The link's state after the last attempt failed with <paramref name="failure"/>: <see cref="LinkState.Broken"/>
    /// when the stream failed; <see cref="LinkState.NeedsInitialize"/> when a multi-frame exchange was cut;
    /// <see cref="LinkState.Ready"/> after a complete error answer (an <see cref="EndCodeException"/>); else
    /// <see cref="LinkState.NeedsResync"/>, since a late answer may still come.
    /// </summary>
    public LinkState After(Exception failure) => failure switch
    {
        HostLinkConnectionException => LinkState.Broken,
        _ when _ifStopped == LinkState.NeedsInitialize => LinkState.NeedsInitialize,
        EndCodeException when _ifStopped == LinkState.Ready => LinkState.Ready,
        _ => LinkState.NeedsResync,
    };

    /// <summary>
    /// Carries <paramref name="request"/> and decodes its answer. While an earlier command's answer may still come out of
    /// turn (<see cref="AnswerTiming.MayBeOutOfTurn"/>), a C-mode answer is checked with a TS behind it: a late answer
    /// taken for this command's would have this command's own right behind it. With <see cref="VerifyAnswers"/> every C-mode answer is
    /// so checked, and a read carried while the unit may be out of turn is carried a second time and taken only when both
    /// answers agree: a late answer may have stood in for this one's, lost on the line.
    /// </summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    public async ValueTask<TResult> RunAsync<TState, TResult>(FrameChannel channel, HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state)
    {
        Reset();
        StartedAt = _time.GetTimestamp();
        bool mayBeOutOfTurn = _answerTiming.MayBeOutOfTurn(request.Unit);
        bool shouldVerify = (VerifyAnswers || mayBeOutOfTurn) && IsUnmatched(request);
        bool carryTwice = VerifyAnswers && shouldVerify && request.ReadOnly && mayBeOutOfTurn;
        await CarryOnceAsync(channel, request, shouldVerify).ConfigureAwait(false);
        if (carryTwice)
        {
            int length = _textLength;
            if (_confirmed.Length < length)
            {
                _confirmed = new byte[Math.Max(length, _confirmed.Length * 2)];
            }

            _text.AsSpan(0, length).CopyTo(_confirmed);
            await CarryOnceAsync(channel, request, shouldVerify).ConfigureAwait(false);
            if (!_text.AsSpan(0, _textLength).SequenceEqual(_confirmed.AsSpan(0, length)))
            {
                throw new HostLinkFrameException(
                    FrameError.Stale,
                    $"The answer to {request.Header} from unit {request.Unit:D2} could not be confirmed: an earlier command's answer may still come out of turn, and the same command sent again was answered differently (VerifyAnswers).");
            }
        }

        return decode(_text.AsSpan(0, _textLength), state);
    }

    /// <summary>Sends <paramref name="request"/>, reads its answer's text (joined, in <see cref="_text"/>) and, if asked, verifies it.</summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder))]
#endif
    private async ValueTask CarryOnceAsync(FrameChannel channel, HostLinkRequest request, bool verify)
    {
        ExchangeShape shape = request.Shape;
        _early = null;

        // Send: frame by frame; between command frames the PLC answers a bare CR (or an error at once).
        int offset = 0;
        int sentChars = 0;
        bool first = true;
        bool final;
        int preReadAt = 0;
        int preReadEnd = 0;
        do
        {
            int remaining = request.Message.Length - offset;
            int length;
            if (shape.SingleFrameOnly)
            {
                length = remaining;
                final = true;
            }
            else
            {
                length = FrameWriter.NextSegmentLength(remaining, first, shape.FixedLength, shape.AtomLength, out final);
            }

            int frameLength = FrameWriter.WriteFrame(request.Message.Span.Slice(offset, length), final, _tx);
            _ifStopped = final ? LinkState.NeedsResync : LinkState.NeedsInitialize;
            Sending(frameLength);
            await channel.WriteAsync(_tx.AsMemory(0, frameLength)).ConfigureAwait(false);
            sentChars = frameLength;
            FramesSent++;
            if (_localEcho)
            {
                await channel.ReadEchoAsync(_tx.AsMemory(0, frameLength), FrameTimeout(frameLength, 0)).ConfigureAwait(false);
            }

            offset += length;
            first = false;
            if (!final)
            {
                int n = await channel.ReadFrameAsync(expectStart: false, FrameTimeout(frameLength, 1)).ConfigureAwait(false);
                int at = channel.Frame(n).IndexOf((byte)'@');
                if (at >= 0)
                {
                    // The PLC answered before the last frame: an error for what it has seen so far.
                    CheckArrival(channel, n - at, request, first: true, single: IsFinal(channel.Frame(n)));
                    preReadAt = at;
                    preReadEnd = n;
                    _ifStopped = LinkState.NeedsResync;
                    break;
                }
            }
        }
        while (!final);

        if (!shape.ExpectsAnswer)
        {
            _ifStopped = LinkState.Ready;
            return;
        }

        // Receive: the first frame, then each continuation after our bare CR. An answer that may span frames is cut if
        // its first frame is lost or damaged: the PLC then holds the rest and takes any command, a TS fence included,
        // as the delimiter asking for it; only INITIALIZE ends that.
        _textLength = 0;
        _ifStopped = preReadEnd == 0 && shape.AnswerMaySpanFrames ? LinkState.NeedsInitialize : LinkState.NeedsResync;
        if (preReadEnd == 0)
        {
            TimeSpan firstTimeout = FrameTimeout(sentChars, shape.MaxFirstAnswerFrame);
            try
            {
                preReadEnd = await channel.ReadFrameAsync(expectStart: true, firstTimeout).ConfigureAwait(false);
                if (IsOwnEcho(channel, request, preReadEnd, sentChars))
                {
                    // A line that echoes (2-wire RS-485) with LocalEcho off: our own frame is not the answer.
                    preReadEnd = await channel.ReadFrameAsync(expectStart: true, firstTimeout).ConfigureAwait(false);
                }
            }
            catch (Exception e) when (e is HostLinkTimeoutException or OperationCanceledException)
            {
                // The command went out and nothing came back: its answer may yet arrive, out of turn.
                _answerTiming.AnswerOwed(request.Unit);
                throw;
            }

            CheckArrival(channel, preReadEnd, request, first: true, single: IsFinal(channel.Frame(preReadEnd)));
        }

        FramesReceived++;
        FrameInfo info = FirstFrame(channel.Frame(preReadEnd).Slice(preReadAt), request);
        while (!info.IsFinal)
        {
            _ifStopped = LinkState.NeedsInitialize;
            Sending(Delimiter.Length);
            await channel.WriteAsync(Delimiter).ConfigureAwait(false);
            if (_localEcho)
            {
                await channel.ReadEchoAsync(Delimiter, FrameTimeout(1, 0)).ConfigureAwait(false);
            }

            int len = await channel.ReadFrameAsync(expectStart: false, FrameTimeout(1, FrameWriter.MaxContinuationFrameLength)).ConfigureAwait(false);
            FramesReceived++;
            CheckArrival(channel, len, request, first: false, single: false);
            info = Continuation(channel, len, request);
        }

        _ifStopped = LinkState.Ready;
        if (channel.HoldsFrameStart)
        {
            // A PLC sends one answer a command: another frame already behind it means the line is out of step, and the
            // frame taken may have been an earlier command's late answer with this command's own right behind it. (A
            // stray byte a 2-wire line leaves when the PLC releases it is no frame: the next read skips it as noise.)
            throw new HostLinkFrameException(
                FrameError.Stale,
                $"Another frame came right behind the answer to {request.Header} from unit {request.Unit:D2}: the line delivers answers out of turn, so the answer taken may have been an earlier command's.");
        }

        if (_early is not null || verify)
        {
            await CheckWithTestAsync(channel, request).ConfigureAwait(false);
        }
    }

    /// <summary>
    /// Whether an answer to <paramref name="request"/> carries nothing that ties it to its command: C-mode answers (FINS
    /// answers carry the command's service ID, and a TS answer its own text).
    /// </summary>
    private static bool IsUnmatched(HostLinkRequest request)
        => request.Header != CModeCommands.Fins.Header && request.Header != CModeCommands.Test.Header;

    /// <summary>
    /// Puts the answer just read to a TS check: the echo must be the next frame, and an answer that came too early
    /// stands only if the echo shows the line runs faster than configured.
    /// </summary>
    private async ValueTask CheckWithTestAsync(FrameChannel channel, HostLinkRequest request)
    {
        bool lineAsConfigured = await _resynchroniser.VerifyAsync(channel, request.Unit, request.Header).ConfigureAwait(false);
        if (_early is { } early && lineAsConfigured)
        {
            _answerTiming.Settled(request.Unit);
            throw new HostLinkFrameException(FrameError.Stale, early);
        }
    }

    private void Sending(int characters)
    {
        _sentAt = _time.GetTimestamp();
        _sentChars = characters;
    }

    /// <summary>
    /// Judges an answer frame of <paramref name="length"/> characters by when it was complete (<see cref="AnswerTiming"/>).
    /// One complete before the last write and the frame itself could have crossed the line is a late answer to an earlier
    /// command, unless the line runs faster than configured: a one-frame answer is put to a TS check once read
    /// (<see cref="CheckWithTestAsync"/>), a frame of a longer answer is refused at once (a TS in its middle would ask the PLC
    /// for the next frame). A first frame that comes later than the unit has lately been answering, while an earlier
    /// answer is owed, is refused at once: it may be that answer standing in for one lost on the line.
    /// </summary>
    private void CheckArrival(FrameChannel channel, int length, HostLinkRequest request, bool first, bool single)
    {
        TimeSpan elapsed = _time.GetElapsedTime(_sentAt, channel.FrameArrivedAt);
        // Only a unit that owes an answer, or whose line has lately delivered out of turn, has a late answer to give: an
        // early answer of any other is the line running faster than configured (or a test host's scheduling), not stale.
        if (_answerTiming.IsTooEarly(elapsed, _sentChars, length) && _answerTiming.MayBeOutOfTurn(request.Unit))
        {
            _early = $"An answer to {request.Header} from unit {request.Unit:D2} was complete {Math.Max(0, elapsed.TotalMilliseconds):0.0} ms after the command was sent, before the command and its answer could have crossed a {_timing.BaudRate} bps line ({_answerTiming.Earliest(_sentChars + length).TotalMilliseconds:0.0} ms): it is a late answer to an earlier command, not this one.";
            if (!single)
            {
                _answerTiming.Settled(channel.Frame(length));
                throw new HostLinkFrameException(FrameError.Stale, _early);
            }

            return;
        }

        if (!first)
        {
            return;
        }

        if (_answerTiming.IsLateWhileOwed(request.Unit, elapsed, _sentChars, length, out TimeSpan usual))
        {
            // Taken to be the owed answer: this command's own was probably lost.
            _answerTiming.Settled(channel.Frame(length));
            throw new HostLinkFrameException(
                FrameError.Stale,
                $"An answer to {request.Header} from unit {request.Unit:D2} came {(elapsed - _timing.WireTime(_sentChars + length)).TotalMilliseconds:0} ms after its characters could have crossed the line, where the unit has lately answered within {usual.TotalMilliseconds:0} ms, while the answer to an earlier command that timed out may still come: it may be that answer, so it is not taken.");
        }

        _answerTiming.Answered(request.Unit, elapsed, _sentChars, length);
    }

    /// <summary>Whether a frame ends as the last of an answer does (<c>*</c> CR), before it is checked.</summary>
    private static bool IsFinal(ReadOnlySpan<byte> frame) => frame.Length >= 2 && frame[frame.Length - 2] == (byte)'*';

    /// <summary>Checks a first answer frame and takes its text.</summary>
    private FrameInfo FirstFrame(ReadOnlySpan<byte> frame, HostLinkRequest request)
    {
        FrameInfo info = FrameParser.ParseFirst(frame);
        _ifStopped = info.IsFinal ? LinkState.Ready : LinkState.NeedsInitialize;
        CModeResponse.CheckAnswerHeader(frame, info, request.Unit, request.Header);
        AnswerFraming?.CheckFrame(request.Header, first: true, info.IsFinal, info.TextLength);
        AppendText(info.Text(frame), request);
        return info;
    }

    private FrameInfo Continuation(FrameChannel channel, int length, HostLinkRequest request)
    {
        ReadOnlySpan<byte> frame = channel.Frame(length);
        FrameInfo info = FrameParser.ParseContinuation(frame);
        AnswerFraming?.CheckFrame(request.Header, first: false, info.IsFinal, info.TextLength);
        AppendText(info.Text(frame), request);
        return info;
    }

    /// <summary>Whether the frame just read is our own last frame coming back, where no correct answer can equal the command.</summary>
    private bool IsOwnEcho(FrameChannel channel, HostLinkRequest request, int length, int sentLength)
        => !_localEcho
            && !request.Shape.AnswerCanEqualCommand
            && length == sentLength
            && channel.Frame(length).SequenceEqual(_tx.AsSpan(0, sentLength));

    private void AppendText(ReadOnlySpan<byte> text, HostLinkRequest request)
    {
        if (_textLength + text.Length > request.Shape.MaxAnswerText)
        {
            throw new HostLinkFrameException(FrameError.WrongLength, $"The answer to {request.Header} is longer than the {request.Shape.MaxAnswerText} characters it can hold.");
        }

        if (_textLength + text.Length > _text.Length)
        {
            Array.Resize(ref _text, Math.Max(_text.Length * 2, _textLength + text.Length));
        }

        text.CopyTo(_text.AsSpan(_textLength));
        _textLength += text.Length;
    }
}
