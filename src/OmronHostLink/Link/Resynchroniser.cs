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
    private readonly byte[] _fence = new byte[CModeCommand.PrefixLength + TokenLength + FrameWriter.FinalOverhead];

    public Resynchroniser(LineTiming timing, TimeSpan turnaround, TimeProvider time, bool localEcho)
    {
        _timing = timing;
        _turnaround = turnaround;
        _time = time;
        _localEcho = localEcho;
    }

    /// <summary>Bytes discarded by the last resynchronisation.</summary>
    public long Discarded { get; private set; }

    /// <summary>The deadline of the last fence.</summary>
    public TimeSpan FenceTimeout { get; private set; }

    /// <summary>Sends <c>@**</c>: every unit on the line resets its Host Link transmission control.</summary>
    public static ValueTask InitializeAsync(FrameChannel channel) => channel.WriteAsync(Initialize);

    /// <summary>Discards what is buffered and fences: first at <paramref name="failedUnit"/>, then at <paramref name="requestUnit"/>.</summary>
    /// <remarks>
    /// A fence answer can itself be hit by line damage, so a second fence is tried before giving up; it goes to the unit
    /// the caller wants, since a unit that did not echo a fresh TS within its deadline is not talking.
    /// </remarks>
    public async ValueTask<ResyncOutcome> FenceAsync(FrameChannel channel, int failedUnit, int requestUnit)
    {
        Discarded = channel.Discard();
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
        Discarded = channel.Discard();
        long started = _time.GetTimestamp();
        ResyncOutcome outcome = await FenceOnceAsync(channel, unit, turnaround).ConfigureAwait(false);
        return outcome == ResyncOutcome.Answered ? _time.GetElapsedTime(started) : null;
    }

    /// <summary>
    /// Sends one fence to <paramref name="unit"/> and discards every frame until its echo or the deadline; the unit's
    /// allowance to start answering is <paramref name="turnaround"/>.
    /// </summary>
    private async ValueTask<ResyncOutcome> FenceOnceAsync(FrameChannel channel, int unit, TimeSpan turnaround)
    {
        ResyncOutcome outcome = ResyncOutcome.Unanswered;
        int frameLength = WriteFence(unit);
        await channel.WriteAsync(_fence.AsMemory(0, frameLength)).ConfigureAwait(false);
        if (_localEcho)
        {
            await channel.ReadEchoAsync(_fence.AsMemory(0, frameLength), _timing.FrameDeadline(frameLength, 0, _turnaround)).ConfigureAwait(false);
        }

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
            catch (HostLinkFrameException)
            {
                // Damaged leftovers of the failed exchange: discarded like any other stale bytes.
                outcome = ResyncOutcome.UnansweredAfterDamagedFrames;
                continue;
            }

            if (channel.Frame(n).SequenceEqual(_fence.AsSpan(0, frameLength)))
            {
                return ResyncOutcome.Answered;
            }

            Discarded += n;
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
