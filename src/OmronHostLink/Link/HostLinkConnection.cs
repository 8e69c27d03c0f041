using System.Runtime.CompilerServices;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Logging.Abstractions;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The one owner of the wire: one transaction at a time over one transport, with its <see cref="LinkState"/> in one
/// place. Every transaction (a request, an INITIALIZE, a presence probe) runs in the same scope: it waits for the gate,
/// opens the transport if the link is <see cref="LinkState.Closed"/>, runs its exchange over the
/// <see cref="FrameChannel"/>, and on failure takes the state the failure leaves (<see cref="TransactionAttempt.After"/>),
/// closing a lost stream at once. Retries live here.
/// </summary>
/// <remarks>
/// The parts: <see cref="FrameChannel"/> (bytes, frames, per-frame deadlines), <see cref="TransactionAttempt"/> (one
/// exchange), <see cref="Resynchroniser"/> (<c>@**</c> and the TS fence), <see cref="SendSpacing"/> (the gap between
/// exchanges), <see cref="CommandTelemetry"/> (per command, not per attempt). Deadlines come from the
/// <see cref="LineTiming"/> and run on the options' <see cref="TimeProvider"/>.
/// </remarks>
internal sealed class HostLinkConnection : IAsyncDisposable, IDisposable
{
    private readonly LinkTransport _transport;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly SendSpacing _spacing;
    private readonly SemaphoreSlim _gate = new(1, 1);
    private readonly TransactionAttempt _attempt;
    private readonly Resynchroniser _resynchroniser;
    private readonly HostLinkInstruments _instruments;
    private readonly AnswerTiming _answerTiming;

    private readonly CaptureTap? _trace;
    private ObserverTap? _observer;
    private LinkStatus _status = new(LinkState.Closed);
    private int _sid;

    public HostLinkConnection(IHostLinkTransport transport, HostLinkConnectionOptions options)
    {
        _time = options.TimeProvider;
        _spacing = new SendSpacing(options);
        Timing = transport.LineTiming ?? options.LineTiming;
        _logger = options.LoggerFactory?.CreateLogger("OmronHostLink") ?? NullLogger.Instance;
        LinkName = options.LinkName ?? (transport as SerialTransport)?.PortName ?? transport.Description;
        _answerTiming = new AnswerTiming(Timing, _time, _logger, LinkName);
        _resynchroniser = new Resynchroniser(Timing, options.TurnaroundAllowance, _time, options.LocalEcho, _answerTiming);
        _attempt = new TransactionAttempt(Timing, options.TurnaroundAllowance, options.LocalEcho, _time, _answerTiming, _resynchroniser)
        {
            AnswerFraming = options.AnswerFraming,
            VerifyAnswers = options.VerifyAnswers,
        };
        _instruments = HostLinkInstruments.For(options.MeterFactory);
        _transport = new LinkTransport(transport, _logger, _time, _instruments, LinkName);
        if (options.TraceFile is { } traceFile)
        {
            _trace = CaptureTap.Create(traceFile);
            Tap = _trace;
        }
    }

    /// <summary>Where the link stands between transactions.</summary>
    public LinkState State => _status.State;

    /// <summary>Whether answers are checked for arriving before their command could have been answered (<see cref="AnswerTiming"/>).</summary>
    internal bool ChecksAnswerTiming => _answerTiming.Armed;

    /// <summary>Bytes received and not yet taken (0 when closed): between exchanges, what came while nothing was outstanding.</summary>
    internal int Held => _transport.OpenChannel()?.Held ?? 0;

    /// <summary>Whether a TS fence came back faster than the configured line speed allows.</summary>
    internal bool LineFasterThanConfigured => _answerTiming.FasterThanConfigured;

    /// <summary>How often the transport has been opened: a change tells what a PLC held for this link (QQ registrations) may be gone.</summary>
    public long Openings => _transport.Openings;

    /// <summary>The timing every deadline is computed from.</summary>
    public LineTiming Timing { get; }

    public string Description => _transport.Description;

    /// <summary>The link's name in metrics and traces.</summary>
    public string LinkName { get; }

    /// <summary>Observes every frame sent and received (for the console's --verbose); one subscriber of <see cref="Tap"/>.</summary>
    public Action<bool, ReadOnlyMemory<byte>>? FrameObserver
    {
        get => _observer?.Observer;
        set
        {
            _observer = value is null ? null : new ObserverTap(value);
            Tap = FrameTap.Combine(_trace, _observer);
        }
    }

    /// <summary>The link's frame tap: the trace file and the frame observer, told of every frame the link sends and takes.</summary>
    public FrameTap? Tap { get; private set; }

    /// <summary>The next FINS service ID: every FINS exchange carries its own, so an answer to another one is refused.</summary>
    public byte NextSid() => unchecked((byte)Interlocked.Increment(ref _sid));

    /// <summary>Runs one request, repeating it up to <paramref name="retries"/> times after a timeout or damage.</summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    public async ValueTask<TResult> ExecuteAsync<TState, TResult>(HostLinkRequest request, int retries, ResponseDecoder<TState, TResult> decode, TState state, CancellationToken cancellationToken)
    {
        request.CheckLength();
        int attempt = 0;
        var telemetry = new CommandTelemetry(_instruments, _time, LinkName, _transport.Transport, request);
        try
        {
            while (true)
            {
                cancellationToken.ThrowIfCancellationRequested();
                try
                {
                    TResult result = await TransactAsync(
                        static (link, channel, call) => link.CarryAsync(channel, call.request, call.decode, call.state),
                        (request, decode, state),
                        request.Unit,
                        request.Header,
                        telemetry.Frames,
                        cancellationToken).ConfigureAwait(false);
                    telemetry.Succeeded(attempt);
                    return result;
                }
                catch (Exception e) when (attempt < retries && IsRetryable(e) && !cancellationToken.IsCancellationRequested)
                {
                    attempt++;
                    telemetry.Retried(e);
                    HostLinkLog.Retry(_logger, request.Unit, request.Header, e.Message, attempt, retries);
                }
                catch (HostLinkTimeoutException e) when (!cancellationToken.IsCancellationRequested)
                {
                    // Said in the caller's terms: the command that went unanswered and the time it cost in all. The last
                    // deadline may have been a resynchronisation fence's, which the caller never asked for; that detail
                    // stays with the inner exception.
                    TimeSpan total = telemetry.Elapsed;
                    throw new HostLinkTimeoutException(
                        $"No answer from unit {request.Unit:D2} to {request.Header} on {_transport.Description}: waited {total.TotalMilliseconds:0} ms in all ({attempt + 1} attempt{(attempt == 0 ? "" : "s")}).",
                        total,
                        e);
                }
            }
        }
        catch (Exception e)
        {
            telemetry.Failed(e, attempt);
            throw;
        }
    }

    /// <summary>Sends <c>@**</c> (INITIALIZE), which has no answer; a cut exchange needs no INITIALIZE of its own after it.</summary>
    public async ValueTask InitializeAsync(CancellationToken cancellationToken)
        => await TransactAsync(static (link, channel, _) => link.InitializeLineAsync(channel), 0, 0, "**", null, cancellationToken).ConfigureAwait(false);

    /// <summary>
    /// Probes whether <paramref name="unit"/> answers: one TS with a fresh random token, never retried, waiting the
    /// frame's wire time both ways plus <paramref name="turnaround"/>. The probe is a resynchronisation in itself
    /// (<c>@**</c> first if a multi-frame exchange was cut, buffered bytes discarded, every frame before the echo thrown
    /// away), so no fence precedes it and a silent unit costs one deadline; the link then stays
    /// <see cref="LinkState.NeedsResync"/> and the next request fences at its own unit: a late echo of the probe carries
    /// the probe's token, which no later fence takes for its own, so fencing the silent unit again would cost a second
    /// deadline and prove nothing more (a demoted unit is probed once a period while its neighbours are polled).
    /// </summary>
    /// <returns>The round-trip time, or null when the unit did not echo the token in time.</returns>
    public ValueTask<TimeSpan?> ProbeAsync(int unit, TimeSpan turnaround, CancellationToken cancellationToken)
        => TransactAsync(static (link, channel, probe) => link.ProbeAsync(channel, probe.unit, probe.turnaround), (unit, turnaround), unit, CModeCommands.Test.Header, null, cancellationToken);

    /// <summary>
    /// Closes the link at once, from any thread, waiting for nothing: an exchange in progress fails with a
    /// <see cref="HostLinkConnectionException"/> (its inner exception an <see cref="ObjectDisposedException"/>), the
    /// transport is closed synchronously, and later calls throw <see cref="ObjectDisposedException"/>.
    /// </summary>
    public void Dispose()
    {
        if (!_transport.CloseAtOnce())
        {
            return;
        }

        _trace?.Dispose();

        // Between exchanges the link is tidied here; during one, the exchange does it as it fails.
        if (_gate.Wait(0))
        {
            try
            {
                _transport.ForgetChannel();
                _status = new LinkStatus(LinkState.Disposed);
            }
            finally
            {
                _gate.Release();
            }
        }
    }

    public async ValueTask DisposeAsync()
    {
        if (State == LinkState.Disposed || _transport.ClosedAtOnce)
        {
            _transport.MarkDisposed();
            return;
        }

        await _gate.WaitAsync().ConfigureAwait(false);
        try
        {
            if (State != LinkState.Disposed)
            {
                await _transport.DisposeAsync().ConfigureAwait(false);
                _status = new LinkStatus(LinkState.Disposed);
                _trace?.Dispose();
            }
        }
        finally
        {
            _gate.Release();
        }
    }

    private static bool IsRetryable(Exception e)
        => e is HostLinkTimeoutException or HostLinkFrameException or EndCodeException { ReportsLineDamage: true };

    /// <summary>
    /// The scope every transaction runs in: the gate, the transport opened if closed, the caller's token on the channel,
    /// the exchange, and on failure the state the failure leaves (out of step with <paramref name="unit"/>; a lost
    /// stream closed before the failure leaves the link). Frames are counted under the gate: the next caller reuses
    /// the attempt.
    /// </summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    private async ValueTask<TResult> TransactAsync<TArg, TResult>(Func<HostLinkConnection, FrameChannel, TArg, ValueTask<TResult>> exchange, TArg arg, int unit, string header, FrameTally? frames, CancellationToken cancellationToken)
    {
        await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            _attempt.Reset();
            FrameChannel channel = _transport.OpenChannel() ?? await OpenAsync(cancellationToken).ConfigureAwait(false);
            await _spacing.WaitAsync(unit, cancellationToken).ConfigureAwait(false);
            if (State == LinkState.Ready && channel.HoldsFrameStart)
            {
                // Nothing was outstanding, so a frame that came is an answer out of turn: the line is not in step. (Bytes
                // without a frame's start are noise, which the next read skips.)
                HostLinkLog.ArrivedWhileIdle(_logger, LinkName, channel.Held);
                _status = new LinkStatus(LinkState.NeedsResync, unit);
            }

            channel.Tap = Tap;
            channel.Begin(cancellationToken, unit, header);
            try
            {
                TResult result = await exchange(this, channel, arg).ConfigureAwait(false);
                if (_attempt.StartedAt != 0)
                {
                    // A request's answer (not a probe's or an INITIALIZE): the unit's response time, fence excluded.
                    _instruments.Exchange(LinkName, unit, header, _time.GetElapsedTime(_attempt.StartedAt));
                }

                return result;
            }
            catch (Exception e)
            {
                LinkState next = _attempt.After(e);
                if (next == LinkState.Broken)
                {
                    await BreakAsync(e).ConfigureAwait(false);
                    throw;
                }

                if (next > State)
                {
                    _status = new LinkStatus(next, unit);
                }

                HostLinkLog.Failed(_logger, unit, header, e.Message);
                throw;
            }
            finally
            {
                channel.End();
                _spacing.ExchangeEnded();
            }
        }
        finally
        {
            frames?.Add(_attempt);
            _gate.Release();
        }
    }

    /// <summary>Carries a request, resynchronising first if the last exchange failed; in step and unlogged, the attempt itself.</summary>
    private ValueTask<TResult> CarryAsync<TState, TResult>(FrameChannel channel, HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state)
        => State == LinkState.Ready && !_logger.IsEnabled(LogLevel.Debug)
            ? _attempt.RunAsync(channel, request, decode, state)
            : ResynchroniseAndCarryAsync(channel, request, decode, state);

#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    private async ValueTask<TResult> ResynchroniseAndCarryAsync<TState, TResult>(FrameChannel channel, HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state)
    {
        if (State is LinkState.NeedsInitialize or LinkState.NeedsResync)
        {
            await ResynchroniseAsync(channel, request.Unit).ConfigureAwait(false);
        }

        long started = _time.GetTimestamp();
        TResult result = await _attempt.RunAsync(channel, request, decode, state).ConfigureAwait(false);

        HostLinkLog.Transaction(_logger, request.Unit, request.Header, _time.GetElapsedTime(started).TotalMilliseconds, _attempt.Frames);
        return result;
    }

    /// <summary>Brings the line back in step before the request; throws (and stays out of step) if no fence was echoed.</summary>
    private async ValueTask ResynchroniseAsync(FrameChannel channel, int requestUnit)
    {
        if (State == LinkState.NeedsInitialize)
        {
            await InitializeLineAsync(channel).ConfigureAwait(false);
        }

        int failedUnit = _status.Unit == LinkStatus.AnyUnit ? requestUnit : _status.Unit;
        ResyncOutcome outcome = await _resynchroniser.FenceAsync(channel, failedUnit, requestUnit).ConfigureAwait(false);
        HostLinkLog.Resync(_logger, failedUnit, _resynchroniser.Discarded, outcome);
        if (outcome == ResyncOutcome.Answered)
        {
            _status = new LinkStatus(LinkState.Ready);
            return;
        }

        // Not in step yet: this exchange fails and the next one fences again, first at the unit this one wanted.
        _status = new LinkStatus(LinkState.NeedsResync, requestUnit);
        if (_resynchroniser.Flood is { } flood)
        {
            // The line carries characters without end: that, not a silent unit, is what the caller needs to hear.
            throw new HostLinkFrameException(flood.Error, flood.Message);
        }

        TimeSpan timeout = _resynchroniser.FenceTimeout;
        throw new HostLinkTimeoutException(
            $"No answer from unit {requestUnit:D2} on {_transport.Description} within {timeout.TotalMilliseconds:0} ms (it did not echo the TS check sent to resynchronise the link after a failed exchange).",
            timeout);
    }

    /// <summary>Sends <c>@**</c>: every unit resets its transmission control, so a cut exchange now needs only a fence.</summary>
    private async ValueTask<bool> InitializeLineAsync(FrameChannel channel)
    {
        await Resynchroniser.InitializeAsync(channel).ConfigureAwait(false);
        if (State == LinkState.NeedsInitialize)
        {
            _status = new LinkStatus(LinkState.NeedsResync, _status.Unit);
        }

        return true;
    }

    /// <summary>The presence probe under the gate: INITIALIZE if a multi-frame exchange was cut, then one fence.</summary>
    private async ValueTask<TimeSpan?> ProbeAsync(FrameChannel channel, int unit, TimeSpan turnaround)
    {
        if (State == LinkState.NeedsInitialize)
        {
            await InitializeLineAsync(channel).ConfigureAwait(false);
        }

        // Until the echo arrives the link is out of step; a failure anywhere below leaves it so.
        _status = new LinkStatus(LinkState.NeedsResync, unit);
        TimeSpan? roundTrip = await _resynchroniser.ProbeAsync(channel, unit, turnaround).ConfigureAwait(false);
        if (roundTrip is null)
        {
            _status = new LinkStatus(LinkState.NeedsResync, LinkStatus.AnyUnit);
            HostLinkLog.Failed(_logger, unit, CModeCommands.Test.Header, $"No answer to a presence probe within {_resynchroniser.FenceTimeout.TotalMilliseconds:0} ms.");
        }
        else
        {
            _status = new LinkStatus(LinkState.Ready);
        }

        return roundTrip;
    }

    /// <summary>Opens the closed transport: the link is <see cref="LinkState.Ready"/>.</summary>
    private async ValueTask<FrameChannel> OpenAsync(CancellationToken cancellationToken)
    {
        FrameChannel channel = await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        _answerTiming.Reopened(timed: _transport.Transport is not SerialTransport { IsPseudoTerminal: true });
        _status = new LinkStatus(LinkState.Ready);
        return channel;
    }

    /// <summary>The stream failed: the link is <see cref="LinkState.Broken"/> and its transport is closed now, not later.</summary>
    private async ValueTask BreakAsync(Exception reason)
    {
        _status = new LinkStatus(LinkState.Broken);
        HostLinkLog.Lost(_logger, _transport.Description, reason.Message);
        await _transport.CloseAsync(lost: true).ConfigureAwait(false);
        _status = new LinkStatus(_transport.IsDisposed ? LinkState.Disposed : LinkState.Closed);
    }
}
