using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// Brings the line back in step after a failed exchange: <c>@**</c> (INITIALIZE) where a multi-frame exchange was cut,
/// then the buffered bytes are discarded and a TS (TEST) fence with a random token goes to the unit; every frame until
/// its echo is discarded. A PLC answers in order, so any late answer to the old request arrives before the echo.
/// </summary>
internal sealed class Resynchroniser
{
    /// <summary>How many TS fences a resynchronisation tries before the exchange fails.</summary>
    public const int FenceAttempts = 2;

    /// <summary>Characters of random token a fence carries.</summary>
    private const int TokenLength = 8;

    private static readonly Random TokenRandom = new();
    private static readonly ReadOnlyMemory<byte> Initialize = CModeFrames.Initialize.ToArray();

    private readonly LineTiming _timing;
    private readonly TimeSpan _turnaround;
    private readonly TimeProvider _time;
    private readonly bool _localEcho;
    private readonly AnswerTiming _answerTiming;
    private readonly byte[] _fence = new byte[CModeCommand.PrefixLength + TokenLength + FrameWriter.FinalOverhead];

    public Resynchroniser(LineTiming timing, TimeSpan turnaround, TimeProvider time, bool localEcho, AnswerTiming answerTiming)
    {
        _timing = timing;
        _turnaround = turnaround;
        _time = time;
        _localEcho = localEcho;
        _answerTiming = answerTiming;
    }

    /// <summary>Bytes discarded by the last resynchronisation.</summary>
    public long Discarded { get; private set; }

    /// <summary>The deadline of the last fence.</summary>
    public TimeSpan FenceTimeout { get; private set; }

    /// <summary>Set when the last unanswered fence saw more characters without a CR than a frame may hold: a flooded line.</summary>
    public HostLinkFrameException? Flood { get; private set; }

    /// <summary>Sends <c>@**</c>: every unit on the line resets its Host Link transmission control.</summary>
    public static ValueTask InitializeAsync(FrameChannel channel) => channel.WriteAsync(Initialize);

    /// <summary>Discards what is buffered and fences: first at <paramref name="failedUnit"/>, then at <paramref name="requestUnit"/>.</summary>
    /// <remarks>
    /// A fence answer can itself be hit by line damage, so a second fence is tried before giving up; it goes to the unit
    /// the caller wants, since a unit that did not echo a fresh TS within its deadline is not talking.
    /// </remarks>
    public async ValueTask<ResyncOutcome> FenceAsync(FrameChannel channel, int failedUnit, int requestUnit)
    {
        Flood = null;
        Discarded = channel.Discard(_answerTiming);

        ResyncOutcome outcome = ResyncOutcome.Unanswered;
        for (int attempt = 0; attempt < FenceAttempts; attempt++)
        {
            ResyncOutcome fence = await FenceOnceAsync(channel, attempt == 0 ? failedUnit : requestUnit, _turnaround).ConfigureAwait(false);
            if (fence == ResyncOutcome.Answered)
            {
                return fence;
            }

            if (fence == ResyncOutcome.UnansweredAfterDamagedFrames)
            {
                outcome = fence;
            }
        }

        return outcome;
    }

    /// <summary>
    /// A presence probe that is its own resynchronisation: discards what is buffered and sends one fence to
    /// <paramref name="unit"/>, waiting the frame's wire time both ways plus <paramref name="turnaround"/>. Never repeated,
    /// so a silent unit costs that one deadline.
    /// </summary>
    /// <returns>The round-trip time, or null when the unit did not echo the token in time.</returns>
    public async ValueTask<TimeSpan?> ProbeAsync(FrameChannel channel, int unit, TimeSpan turnaround)
    {
        Discarded = channel.Discard(_answerTiming);

        long started = _time.GetTimestamp();
        ResyncOutcome outcome = await FenceOnceAsync(channel, unit, turnaround).ConfigureAwait(false);
        return outcome == ResyncOutcome.Answered ? _time.GetElapsedTime(started) : null;
    }

    /// <summary>
    /// Checks that the answer just taken was the unit's answer to the command before it: a TS with a fresh token goes to
    /// <paramref name="unit"/>, and its echo must be the next frame. A PLC answers in order, so a frame that comes first
    /// is an answer out of turn — the one taken may have been another command's.
    /// </summary>
    /// <returns>Whether the echo took at least the configured line's time (<see cref="AnswerTiming.FenceEchoed"/>).</returns>
    /// <exception cref="HostLinkFrameException">Another frame came before the echo (<see cref="FrameError.Stale"/>).</exception>
    /// <exception cref="HostLinkTimeoutException">The echo did not come within its deadline.</exception>
    public async ValueTask<bool> VerifyAsync(FrameChannel channel, int unit, string header)
    {
        (int frameLength, long sentAt) = await SendFenceAsync(channel, unit).ConfigureAwait(false);
        TimeSpan timeout = _timing.FrameDeadline(frameLength, frameLength, _turnaround);
        int n = await channel.ReadFrameAsync(expectStart: true, timeout).ConfigureAwait(false);

        if (!channel.Frame(n).SequenceEqual(_fence.AsSpan(0, frameLength)))
        {
            // A damaged frame is refused as such (its FCS); a sound one that is not the echo came out of turn.
            _answerTiming.Settled(channel.Frame(n));
            FrameParser.ParseFirst(channel.Frame(n));
            throw new HostLinkFrameException(
                FrameError.Stale,
                $"Another frame came from the line between the answer to {header} from unit {unit:D2} and the TS check sent behind it: the line delivers answers out of turn, so the answer taken may have been an earlier command's.",
                channel.Frame(n));
        }

        return _answerTiming.FenceEchoed(unit, _time.GetElapsedTime(sentAt, channel.FrameArrivedAt), frameLength, n);
    }

    /// <summary>Writes a fence with a fresh token to <paramref name="unit"/> (and reads back the line's echo of it).</summary>
    /// <returns>The fence's length and when its write started.</returns>
    private async ValueTask<(int Length, long SentAt)> SendFenceAsync(FrameChannel channel, int unit)
    {
        int frameLength = WriteFence(unit);
        long sentAt = _time.GetTimestamp();
        await channel.WriteAsync(_fence.AsMemory(0, frameLength)).ConfigureAwait(false);
        if (_localEcho)
        {
            await channel.ReadEchoAsync(_fence.AsMemory(0, frameLength), _timing.FrameDeadline(frameLength, 0, _turnaround)).ConfigureAwait(false);
        }

        return (frameLength, sentAt);
    }

    /// <summary>
    /// Sends one fence to <paramref name="unit"/> and discards every frame until its echo or the deadline; the unit's
    /// allowance to start answering is <paramref name="turnaround"/>.
    /// </summary>
    private async ValueTask<ResyncOutcome> FenceOnceAsync(FrameChannel channel, int unit, TimeSpan turnaround)
    {
        ResyncOutcome outcome = ResyncOutcome.Unanswered;
        (int frameLength, long sentAt) = await SendFenceAsync(channel, unit).ConfigureAwait(false);

        // TS is answered with its own characters.
        TimeSpan timeout = _timing.FrameDeadline(frameLength, frameLength, turnaround);
        FenceTimeout = timeout;
        long started = _time.GetTimestamp();
        while (true)
        {
            TimeSpan left = timeout - _time.GetElapsedTime(started);
            if (left <= TimeSpan.Zero)
            {
                return outcome;
            }

            int n;
            try
            {
                n = await channel.ReadFrameAsync(expectStart: true, left > TimeSpan.FromMilliseconds(1) ? left : TimeSpan.FromMilliseconds(1)).ConfigureAwait(false);
            }
            catch (HostLinkTimeoutException)
            {
                return outcome;
            }
            catch (HostLinkFrameException e)
            {
                // Damaged leftovers of the failed exchange: discarded like any other stale bytes.
                outcome = ResyncOutcome.UnansweredAfterDamagedFrames;
                Flood = e.Error == FrameError.TooLong ? e : Flood;
                continue;
            }

            if (channel.Frame(n).SequenceEqual(_fence.AsSpan(0, frameLength)))
            {
                _answerTiming.FenceEchoed(unit, _time.GetElapsedTime(sentAt, channel.FrameArrivedAt), frameLength, n);
                return ResyncOutcome.Answered;
            }

            Discarded += n;
            _answerTiming.Settled(channel.Frame(n));
        }
    }

    /// <summary>Writes a TS fence frame with a fresh random token.</summary>
    /// <returns>The frame's length.</returns>
    private int WriteFence(int unit)
    {
        Span<byte> token = stackalloc byte[TokenLength];
        lock (TokenRandom)
        {
            for (int i = 0; i < token.Length; i++)
            {
                token[i] = HexAscii.Nibble(TokenRandom.Next(16));
            }
        }

        int length = TestCommand.WriteMessage(unit, token, _fence);
        return FrameWriter.WriteFrame(_fence.AsSpan(0, length), final: true, _fence);
    }
}
