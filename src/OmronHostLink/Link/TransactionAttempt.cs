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
    private readonly byte[] _tx = new byte[FrameReader.MaxFrameLength + 8];
    private byte[] _text = new byte[256];
    private int _textLength;

    // The state the line is left in if the exchange stops now: NeedsInitialize inside a multi-frame exchange (the PLC
    // holds the rest of a command or an answer), Ready once the whole answer is in, NeedsResync otherwise.
    private LinkState _ifStopped;

    public TransactionAttempt(LineTiming timing, TimeSpan turnaround, bool localEcho, TimeProvider time)
    {
        _timing = timing;
        _time = time;
        _turnaround = turnaround;
        _localEcho = localEcho;
    }

    /// <summary>The framing of a Serial Communications Unit's Host Link-compatible mode, each answer frame checked against it; null for any.</summary>
    public CompatibleModeFraming? AnswerFraming { get; init; }

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

    /// <summary>Carries <paramref name="request"/> once and decodes its answer.</summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    public async ValueTask<TResult> RunAsync<TState, TResult>(FrameChannel channel, HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state)
    {
        ExchangeShape shape = request.Shape;
        Reset();
        StartedAt = _time.GetTimestamp();

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
            return decode(ReadOnlySpan<byte>.Empty, state);
        }

        // Receive: the first frame, then each continuation after our bare CR. An answer that may span frames is cut if
        // its first frame is lost or damaged: the PLC then holds the rest and takes any command, a TS fence included,
        // as the delimiter asking for it; only INITIALIZE ends that.
        _textLength = 0;
        _ifStopped = preReadEnd == 0 && shape.AnswerMaySpanFrames ? LinkState.NeedsInitialize : LinkState.NeedsResync;
        if (preReadEnd == 0)
        {
            TimeSpan firstTimeout = FrameTimeout(sentChars, shape.MaxFirstAnswerFrame);
            preReadEnd = await channel.ReadFrameAsync(expectStart: true, firstTimeout).ConfigureAwait(false);
            if (IsOwnEcho(channel, request, preReadEnd, sentChars))
            {
                // A line that echoes (2-wire RS-485) with LocalEcho off: our own frame is not the answer.
                preReadEnd = await channel.ReadFrameAsync(expectStart: true, firstTimeout).ConfigureAwait(false);
            }
        }

        FramesReceived++;
        FrameInfo info = FirstFrame(channel.Frame(preReadEnd).Slice(preReadAt), request);
        while (!info.IsFinal)
        {
            _ifStopped = LinkState.NeedsInitialize;
            await channel.WriteAsync(Delimiter).ConfigureAwait(false);
            if (_localEcho)
            {
                await channel.ReadEchoAsync(Delimiter, FrameTimeout(1, 0)).ConfigureAwait(false);
            }

            int len = await channel.ReadFrameAsync(expectStart: false, FrameTimeout(1, FrameWriter.MaxContinuationFrameLength)).ConfigureAwait(false);
            FramesReceived++;
            info = Continuation(channel, len, request);
        }

        _ifStopped = LinkState.Ready;
        return decode(_text.AsSpan(0, _textLength), state);
    }

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
