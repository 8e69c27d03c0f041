using System.Diagnostics;
using System.Runtime.CompilerServices;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Logging.Abstractions;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Transports;

namespace OmronHostLink.Link;

/// <summary>
/// The one owner of the wire: one transaction at a time over one transport, with an explicit <see cref="LinkState"/>.
/// Each call waits for the gate, opens the transport if the link is <see cref="LinkState.Closed"/>, resynchronises if
/// the last exchange failed, runs one <see cref="TransactionAttempt"/> over the <see cref="FrameChannel"/>, and moves
/// the state by how the attempt ended (<see cref="AttemptFailure"/>); retries and telemetry live here.
/// </summary>
/// <remarks>
/// The parts: <see cref="FrameChannel"/> (the stream's bytes, frames, per-frame deadlines), <see cref="TransactionAttempt"/>
/// (one exchange, frame by frame), <see cref="Resynchroniser"/> (<c>@**</c> and the TS fence). Deadlines run on the
/// <see cref="TimeProvider"/> of the options. Telemetry is per command, not per attempt: one duration measurement
/// and one span (<see cref="HostLinkActivities"/>) from the call to its result or final error, each retry counted.
/// </remarks>
internal sealed class HostLinkConnection : IAsyncDisposable
{
    private readonly IHostLinkTransport _transport;
    private readonly HostLinkConnectionOptions _options;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly SemaphoreSlim _gate = new(1, 1);
    private readonly TransactionAttempt _attempt;
    private readonly Resynchroniser _resynchroniser;
    private readonly HostLinkInstruments _instruments;

    private FrameChannel? _channel;
    private Action<bool, ReadOnlyMemory<byte>>? _frameObserver;
    private int _resyncUnit;
    private int _sid;
    private long _lastExchangeEnded;

    public HostLinkConnection(IHostLinkTransport transport, HostLinkConnectionOptions options)
    {
        _transport = transport;
        _options = options;
        _time = options.TimeProvider;
        Timing = transport.LineTiming ?? options.LineTiming;
        _logger = options.LoggerFactory?.CreateLogger("OmronHostLink") ?? NullLogger.Instance;
        _attempt = new TransactionAttempt(Timing, options.TurnaroundAllowance, options.LocalEcho);
        _resynchroniser = new Resynchroniser(_attempt, _time, options.LocalEcho);
        _instruments = HostLinkInstruments.For(options.MeterFactory);
        LinkName = options.LinkName ?? (transport as SerialTransport)?.PortName ?? transport.Description;
    }

    /// <summary>Where the link stands between transactions.</summary>
    public LinkState State { get; private set; } = LinkState.Closed;

    /// <summary>The timing every deadline is computed from.</summary>
    public LineTiming Timing { get; }

    public string Description => _transport.Description;

    /// <summary>The link's name in metrics and traces.</summary>
    public string LinkName { get; }

    /// <summary>Observes every frame sent and received (for the console's --verbose).</summary>
    public Action<bool, ReadOnlyMemory<byte>>? FrameObserver
    {
        get => _frameObserver;
        set
        {
            _frameObserver = value;
            if (_channel is { } channel)
            {
                channel.FrameObserver = value;
            }
        }
    }

    /// <summary>The next FINS service ID: every FINS exchange carries its own, so an answer to another one is refused.</summary>
    public byte NextSid() => unchecked((byte)Interlocked.Increment(ref _sid));

    /// <summary>Runs one request, repeating it up to <paramref name="retries"/> times after a timeout or damage.</summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    public async ValueTask<TResult> ExecuteAsync<TState, TResult>(HostLinkRequest request, int retries, ResponseDecoder<TState, TResult> decode, TState state, CancellationToken cancellationToken)
    {
        ExchangeShape shape = request.Shape;
        if (!shape.MultiFrameCommand && !shape.SingleFrameOnly && request.Message.Length + FrameWriter.FinalOverhead > FrameWriter.MaxFirstFrameLength)
        {
            throw new ArgumentException($"The {request.Header} command is {request.Message.Length + FrameWriter.FinalOverhead} characters long; it must fit one {FrameWriter.MaxFirstFrameLength}-character frame.");
        }

        int attempt = 0;
        int framesSent = 0;
        int framesReceived = 0;
        long started = _time.GetTimestamp();
        Activity? activity = HostLinkActivities.Start(request, LinkName, _transport);
        try
        {
            while (true)
            {
                cancellationToken.ThrowIfCancellationRequested();
                await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
                try
                {
                    TResult result = await RunAsync(request, decode, state, cancellationToken).ConfigureAwait(false);
                    if (_instruments.OperationDuration.Enabled)
                    {
                        _instruments.Operation(LinkName, request.Unit, request.Header, null, _time.GetElapsedTime(started));
                    }

                    if (activity is not null)
                    {
                        HostLinkActivities.Succeeded(activity, framesSent + _attempt.FramesSent, framesReceived + _attempt.FramesReceived, attempt);
                    }

                    return result;
                }
                catch (Exception e) when (attempt < retries && IsRetryable(e) && !cancellationToken.IsCancellationRequested)
                {
                    attempt++;
                    _instruments.Retry(LinkName, request.Unit, request.Header, e);
                    HostLinkLog.Retry(_logger, request.Unit, request.Header, e.Message, attempt, retries);
                }
                catch (HostLinkTimeoutException e) when (!cancellationToken.IsCancellationRequested)
                {
                    // Said in the caller's terms: the command that went unanswered and the time it cost in all. The last
                    // deadline may have been a resynchronisation fence's, which the caller never asked for; that detail
                    // stays with the inner exception.
                    TimeSpan total = _time.GetElapsedTime(started);
                    throw new HostLinkTimeoutException(
                        $"No answer from unit {request.Unit:D2} to {request.Header} on {_transport.Description}: waited {total.TotalMilliseconds:0} ms in all ({attempt + 1} attempt{(attempt == 0 ? "" : "s")}).",
                        total,
                        e);
                }
                finally
                {
                    // Read under the gate: the attempt is the connection's, and the next caller's resets it.
                    framesSent += _attempt.FramesSent;
                    framesReceived += _attempt.FramesReceived;
                    _gate.Release();
                }
            }
        }
        catch (Exception e)
        {
            if (_instruments.OperationDuration.Enabled)
            {
                _instruments.Operation(LinkName, request.Unit, request.Header, e, _time.GetElapsedTime(started));
            }

            if (activity is not null)
            {
                HostLinkActivities.Failed(activity, e, framesSent, framesReceived, attempt);
            }

            throw;
        }
    }

    /// <summary>Sends <c>@**</c> (INITIALIZE), which has no answer; a cut exchange needs no INITIALIZE of its own after it.</summary>
    public async ValueTask InitializeAsync(CancellationToken cancellationToken)
    {
        await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            FrameChannel channel = await OpenedAsync(cancellationToken).ConfigureAwait(false);
            channel.Begin(cancellationToken);
            try
            {
                await Resynchroniser.InitializeAsync(channel).ConfigureAwait(false);
                if (State == LinkState.NeedsInitialize)
                {
                    State = LinkState.NeedsResync;
                }
            }
            catch (HostLinkConnectionException)
            {
                Break();
                throw;
            }
            finally
            {
                await EndAsync(channel).ConfigureAwait(false);
            }
        }
        finally
        {
            _gate.Release();
        }
    }

    /// <summary>
    /// Probes whether <paramref name="unit"/> answers: one TS with a fresh random token, never retried, waiting the
    /// frame's wire time both ways plus <paramref name="turnaround"/>. The probe is a resynchronisation in itself
    /// (<c>@**</c> first if a multi-frame exchange was cut, buffered bytes discarded, every frame before the echo thrown
    /// away), so no fence precedes it and a silent unit costs one deadline; the link then stays
    /// <see cref="LinkState.NeedsResync"/> and the next request fences as after any failed exchange.
    /// </summary>
    /// <returns>The round-trip time, or null when the unit did not echo the token in time.</returns>
    public async ValueTask<TimeSpan?> ProbeAsync(int unit, TimeSpan turnaround, CancellationToken cancellationToken)
    {
        await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            FrameChannel channel = await OpenedAsync(cancellationToken).ConfigureAwait(false);
            await KeepSendIntervalAsync(unit, cancellationToken).ConfigureAwait(false);
            channel.Begin(cancellationToken);
            try
            {
                if (State == LinkState.NeedsInitialize)
                {
                    await Resynchroniser.InitializeAsync(channel).ConfigureAwait(false);
                }

                // Until the echo arrives the link is out of step; a failure anywhere below leaves it so.
                State = LinkState.NeedsResync;
                _resyncUnit = unit;
                TimeSpan? roundTrip = await _resynchroniser.ProbeAsync(channel, unit, turnaround).ConfigureAwait(false);
                if (roundTrip is null)
                {
                    HostLinkLog.Failed(_logger, unit, CModeHeaders.Test, $"No answer to a presence probe within {_resynchroniser.FenceTimeout.TotalMilliseconds:0} ms.");
                }
                else
                {
                    State = LinkState.Ready;
                }

                return roundTrip;
            }
            catch (HostLinkConnectionException e)
            {
                HostLinkLog.Lost(_logger, _transport.Description, e.Message);
                Break();
                throw;
            }
            finally
            {
                await EndAsync(channel).ConfigureAwait(false);
            }
        }
        finally
        {
            _gate.Release();
        }
    }

    public async ValueTask DisposeAsync()
    {
        if (State == LinkState.Disposed)
        {
            return;
        }

        await _gate.WaitAsync().ConfigureAwait(false);
        try
        {
            if (State == LinkState.Disposed)
            {
                return;
            }

            await CloseAsync(lost: false).ConfigureAwait(false);
            State = LinkState.Disposed;
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

    /// <summary>One attempt under the gate: open, resynchronise if needed, carry the request, move the state.</summary>
#if NET
    [AsyncMethodBuilder(typeof(PoolingAsyncValueTaskMethodBuilder<>))]
#endif
    private async ValueTask<TResult> RunAsync<TState, TResult>(HostLinkRequest request, ResponseDecoder<TState, TResult> decode, TState state, CancellationToken cancellationToken)
    {
        _attempt.ResetFrames();
        FrameChannel channel = await OpenedAsync(cancellationToken).ConfigureAwait(false);
        await KeepSendIntervalAsync(request.Unit, cancellationToken).ConfigureAwait(false);
        channel.Begin(cancellationToken);
        try
        {
            if (State is LinkState.NeedsInitialize or LinkState.NeedsResync)
            {
                await ResynchroniseAsync(channel, request.Unit).ConfigureAwait(false);
            }

            long started = _time.GetTimestamp();
            try
            {
                TResult result = await _attempt.RunAsync(channel, request, decode, state).ConfigureAwait(false);
                HostLinkLog.Transaction(_logger, request.Unit, request.Header, _time.GetElapsedTime(started).TotalMilliseconds, _attempt.Frames);
                return result;
            }
            catch (Exception e)
            {
                Failed(e, request);
                throw;
            }
        }
        finally
        {
            await EndAsync(channel).ConfigureAwait(false);
        }
    }

    /// <summary>Moves the state by how the attempt failed.</summary>
    private void Failed(Exception e, HostLinkRequest request)
    {
        AttemptFailure failure = _attempt.Classify(e);
        switch (failure)
        {
            case AttemptFailure.InStep:
                // A complete error answer: the link is still in step.
                HostLinkLog.Failed(_logger, request.Unit, request.Header, e.Message);
                break;
            case AttemptFailure.Lost:
                HostLinkLog.Lost(_logger, _transport.Description, e.Message);
                Break();
                break;
            default:
                State = failure == AttemptFailure.Cut ? LinkState.NeedsInitialize : LinkState.NeedsResync;
                _resyncUnit = request.Unit;
                HostLinkLog.Failed(_logger, request.Unit, request.Header, e.Message);
                break;
        }
    }

    /// <summary>Brings the line back in step before the request; throws (and stays out of step) if no fence was echoed.</summary>
    private async ValueTask ResynchroniseAsync(FrameChannel channel, int requestUnit)
    {
        try
        {
            if (State == LinkState.NeedsInitialize)
            {
                // A multi-frame exchange was cut: INITIALIZE resets every unit's transmission control.
                await Resynchroniser.InitializeAsync(channel).ConfigureAwait(false);
                State = LinkState.NeedsResync;
            }

            ResyncOutcome outcome = await _resynchroniser.FenceAsync(channel, _resyncUnit, requestUnit).ConfigureAwait(false);
            HostLinkLog.Resync(_logger, _resyncUnit, _resynchroniser.Discarded, outcome);
            if (outcome == ResyncOutcome.Answered)
            {
                State = LinkState.Ready;
                return;
            }
        }
        catch (HostLinkConnectionException e)
        {
            HostLinkLog.Lost(_logger, _transport.Description, e.Message);
            Break();
            throw;
        }

        // Not in step yet: this exchange fails and the next one fences again, at the unit it wants.
        _resyncUnit = requestUnit;
        TimeSpan timeout = _resynchroniser.FenceTimeout;
        throw new HostLinkTimeoutException(
            $"No answer from unit {requestUnit:D2} on {_transport.Description} within {timeout.TotalMilliseconds:0} ms (it did not echo the TS check sent to resynchronise the link after a failed exchange).",
            timeout);
    }

    private async ValueTask<FrameChannel> OpenedAsync(CancellationToken cancellationToken)
    {
        if (State == LinkState.Disposed)
        {
            throw new ObjectDisposedException(nameof(HostLinkConnection), $"The link to {_transport.Description} is closed.");
        }

        if (_channel is { } open)
        {
            return open;
        }

        Stream stream = await _transport.OpenAsync(cancellationToken).ConfigureAwait(false);
        var channel = new FrameChannel(stream, _transport.Description, _logger, _time) { FrameObserver = _frameObserver };
        _channel = channel;
        State = LinkState.Ready;
        channel.Start();
        _instruments.Connection(LinkName, +1);
        HostLinkLog.Opened(_logger, _transport.Description);
        return channel;
    }

    /// <summary>The stream failed: the link is broken until its channel is closed at the end of the transaction.</summary>
    private void Break() => State = LinkState.Broken;

    /// <summary>
    /// The one place the next command waits for the send interval: until the gap since the last exchange ended (whatever
    /// it was, answered or not) is the longer of the link's and the unit's.
    /// </summary>
    private Task KeepSendIntervalAsync(int unit, CancellationToken cancellationToken)
    {
        TimeSpan gap = _options.SendIntervalFor(unit);
        if (gap <= TimeSpan.Zero || _lastExchangeEnded == 0)
        {
            return Task.CompletedTask;
        }

        TimeSpan remaining = gap - _time.GetElapsedTime(_lastExchangeEnded);
        if (remaining <= TimeSpan.Zero)
        {
            return Task.CompletedTask;
        }

#if NET
        return Task.Delay(remaining, _time, cancellationToken);
#else
        return _time.Delay(remaining, cancellationToken);
#endif
    }

    private async ValueTask EndAsync(FrameChannel channel)
    {
        channel.End();
        _lastExchangeEnded = _time.GetTimestamp();
        if (State == LinkState.Broken)
        {
            await CloseAsync(lost: true).ConfigureAwait(false);
        }
    }

    /// <summary>Stops the channel and closes the transport: <see cref="LinkState.Closed"/>.</summary>
    private async ValueTask CloseAsync(bool lost)
    {
        FrameChannel? channel = _channel;
        _channel = null;
        channel?.RequestStop();
        try
        {
            await _transport.CloseAsync().ConfigureAwait(false);
        }
        catch (Exception e) when (lost && e is IOException or ObjectDisposedException)
        {
        }

        if (channel is not null)
        {
            await channel.WaitStoppedAsync().ConfigureAwait(false);
            _instruments.Connection(LinkName, -1);
        }

        State = LinkState.Closed;
    }
}
