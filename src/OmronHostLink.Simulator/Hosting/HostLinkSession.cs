using System.Diagnostics;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator.Faults;
using OmronHostLink.Simulator.Protocol;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// One Host Link session of the PLCs on a line over a stream: cuts frames out of the received bytes (noise skipped),
/// runs them through a <see cref="HostLinkExchange"/>, and writes the answers with the answering PLC's turnaround and
/// injected faults, paced at the line's wire speed.
/// </summary>
internal sealed class HostLinkSession
{
    private readonly Dictionary<int, VirtualPlc> _plcs = new();
    private readonly HostLinkExchange _exchange;
    private readonly WirePacer _pacer;
    private readonly SimulatorFrameLog? _log;

    // The line carries one frame at a time: an answer sent out of turn waits for the one being sent, and the other way round.
    private readonly SemaphoreSlim _line = new(1, 1);

    public HostLinkSession(VirtualPlc plc)
        : this([plc])
    {
    }

    /// <summary>A session of several PLCs sharing the line (their unit numbers distinct, their line speed the same).</summary>
    public HostLinkSession(IReadOnlyList<VirtualPlc> plcs)
    {
        var responders = new Dictionary<int, HostLinkResponder>();
        foreach (VirtualPlc plc in plcs)
        {
            var responder = new HostLinkResponder(plc);
            foreach (int unit in plc.Options.Units)
            {
                _plcs[unit] = plc;
                responders[unit] = responder;
            }
        }

        _exchange = new HostLinkExchange(responders);
        _pacer = new WirePacer(plcs[0].Options.BaudRate, plcs[0].Options.BitsPerCharacter);
        _log = plcs[0].Options.FrameLog;
    }

    public Task RunAsync(Stream stream, CancellationToken cancellationToken)
        => FrameLoop.RunAsync(
            stream,
            () => _exchange.ExpectsFirstFrame,
            async (received, arrived) =>
            {
                _log?.Received(received, arrived);
                LinkReply reply = _exchange.Receive(received);
                if (reply.Bytes is not null)
                {
                    await SendAsync(stream, received, reply, cancellationToken).ConfigureAwait(false);
                }
            },
            _exchange.Reset,
            cancellationToken);

    private static readonly TimeSpan OneMillisecond = TimeSpan.FromMilliseconds(1);

    /// <summary>
    /// Waits at least <paramref name="delay"/> by the stopwatch. A timer is due by the coarse system tick, so
    /// <see cref="Task.Delay(TimeSpan, CancellationToken)"/> can end up to one tick (4 ms here) early; a PLC never answers
    /// before its turnaround, so the remainder is waited again.
    /// </summary>
    private static async Task DelayAtLeastAsync(TimeSpan delay, CancellationToken cancellationToken)
    {
        long started = Stopwatch.GetTimestamp();
        TimeSpan left = delay;
        while (left > TimeSpan.Zero)
        {
            await Task.Delay(left < OneMillisecond ? OneMillisecond : left, cancellationToken).ConfigureAwait(false);
            left = delay - Stopwatch.GetElapsedTime(started);
        }
    }

    private async Task SendAsync(Stream stream, byte[] received, LinkReply reply, CancellationToken cancellationToken)
    {
        VirtualPlc plc = _plcs[_exchange.Unit];
        FaultInjector faults = plc.Faults;
        TimeSpan turnaround = plc.Options.Turnaround + reply.Delay;
        FaultPlan plan = reply.IsHandshake ? FaultPlan.None : faults.Plan(reply.Bytes!);
        if (plan.Drop)
        {
            return;
        }

        if (plan.Echo)
        {
            // On a 2-wire line the host hears its own command; that happens while it is sent, before the turnaround.
            await SendOnLineAsync(stream, received, framed: true, cancellationToken).ConfigureAwait(false);
        }
        else if (_pacer.Enabled)
        {
            // The command reached us at once over the stream; on the line its last character arrives only after its
            // wire time, and the turnaround starts then.
            turnaround += _pacer.WireTime(received.Length);
        }

        if (plan.Late || plan.OutOfTurn)
        {
            turnaround += faults.LateBy;
        }

        if (plan.OutOfTurn)
        {
            // Held back while the PLC goes on answering later commands.
            _ = SendOutOfTurnAsync(stream, plan, reply.Bytes!, turnaround, cancellationToken);
            return;
        }

        await WaitAsync(turnaround, cancellationToken).ConfigureAwait(false);
        await SendAnswerAsync(stream, plan, reply.Bytes!, cancellationToken).ConfigureAwait(false);
    }

    private async Task SendOutOfTurnAsync(Stream stream, FaultPlan plan, byte[] answer, TimeSpan delay, CancellationToken cancellationToken)
    {
        try
        {
            await WaitAsync(delay, cancellationToken).ConfigureAwait(false);
            await SendAnswerAsync(stream, plan, answer, cancellationToken).ConfigureAwait(false);
        }
        catch (Exception e) when (e is OperationCanceledException or IOException or ObjectDisposedException)
        {
            // The session ended before the answer's time came.
        }
    }

    private Task WaitAsync(TimeSpan turnaround, CancellationToken cancellationToken)
    {
        if (turnaround <= TimeSpan.Zero)
        {
            return Task.CompletedTask;
        }

        // With wire-time emulation the turnaround is timed as precisely as the characters (Task.Delay can be late by
        // milliseconds on a loaded machine); without it, a timer is enough.
        return _pacer.Enabled ? _pacer.DelayAsync(turnaround, cancellationToken) : DelayAtLeastAsync(turnaround, cancellationToken);
    }

    private async Task SendAnswerAsync(Stream stream, FaultPlan plan, byte[] answer, CancellationToken cancellationToken)
    {
        await _line.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            if (plan.Noise is { } noise)
            {
                await WriteAsync(stream, noise, framed: false, cancellationToken).ConfigureAwait(false);
            }

            await WriteAsync(stream, plan.Shape(answer), framed: plan.TruncateTo < 0, cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            _line.Release();
        }
    }

    private async Task SendOnLineAsync(Stream stream, byte[] bytes, bool framed, CancellationToken cancellationToken)
    {
        await _line.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            await WriteAsync(stream, bytes, framed, cancellationToken).ConfigureAwait(false);
        }
        finally
        {
            _line.Release();
        }
    }

    /// <summary>Writes bytes at the line's pace and logs them with the times their first and last bytes went out.</summary>
    private async Task WriteAsync(Stream stream, byte[] bytes, bool framed, CancellationToken cancellationToken)
    {
        DateTimeOffset first = await _pacer.WriteAsync(stream, bytes, cancellationToken).ConfigureAwait(false);
        _log?.Sent(bytes, first, DateTimeOffset.UtcNow, framed);
    }
}
