using System.Diagnostics;
using System.IO.Pipelines;

namespace OmronHostLink.Link;

/// <summary>Presence probes: one TS that is its own resynchronisation.</summary>
internal sealed partial class HostLinkConnection
{
    /// <summary>
    /// Sends one TS with a fresh random token to <paramref name="unit"/> and waits the frame's wire time plus
    /// <paramref name="turnaround"/> for the echo. Never retried. The probe is a resynchronisation in itself (buffered
    /// bytes are drained and every frame before the echo is discarded, after <c>@**</c> if a multi-frame exchange was
    /// cut), so no TS fence precedes it and a unit that stays silent costs one deadline: the next probe fences in its
    /// own right, and the next request resynchronises as after any failed exchange.
    /// </summary>
    /// <returns>The round-trip time, or null when the unit did not echo the token in time.</returns>
    public async ValueTask<TimeSpan?> ProbeAsync(int unit, TimeSpan turnaround, CancellationToken cancellationToken)
    {
        await _gate.WaitAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            ObjectDisposedExceptionThrowIf();
            await EnsureOpenAsync(cancellationToken).ConfigureAwait(false);
            using var deadline = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
            if (_midExchange)
            {
                await WriteAsync(Protocol.CMode.CModeFrames.Initialize.ToArray(), deadline.Token).ConfigureAwait(false);
                _midExchange = false;
            }

            PipeReader reader = _pipe!.Reader;
            if (reader.TryRead(out ReadResult pending))
            {
                reader.AdvanceTo(pending.Buffer.End);
            }

            // Until the echo arrives the link is out of step; a failure anywhere below leaves it so.
            _needsResync = true;
            _resyncUnit = unit;
            int frameLength = WriteFenceFrame(unit);
            var clock = Stopwatch.StartNew();
            await WriteAsync(_tx.AsMemory(0, frameLength), deadline.Token).ConfigureAwait(false);
            if (_options.LocalEcho)
            {
                await ConsumeEchoAsync(frameLength, deadline, cancellationToken).ConfigureAwait(false);
            }

            TimeSpan timeout = Timing.WireTime(2 * frameLength) + turnaround;
            while (clock.Elapsed < timeout)
            {
                TimeSpan left = timeout - clock.Elapsed;
                int n;
                try
                {
                    n = await ReadFrameAsync(expectStart: true, left > TimeSpan.FromMilliseconds(1) ? left : TimeSpan.FromMilliseconds(1), deadline, cancellationToken).ConfigureAwait(false);
                }
                catch (HostLinkTimeoutException)
                {
                    break;
                }
                catch (HostLinkFrameException)
                {
                    // Damaged leftovers, or a damaged echo: not a presence.
                    continue;
                }

                if (n == frameLength && _frame.AsSpan(0, n).SequenceEqual(_tx.AsSpan(0, frameLength)))
                {
                    _needsResync = false;
                    return clock.Elapsed;
                }
            }

            HostLinkLog.Failed(_logger, unit, "TS", $"No answer to a presence probe within {timeout.TotalMilliseconds:0} ms.");
            return null;
        }
        catch (HostLinkConnectionException e)
        {
            HostLinkLog.Lost(_logger, _transport.Description, e.Message);
            await DropAsync(e).ConfigureAwait(false);
            throw;
        }
        finally
        {
            _gate.Release();
        }
    }
}
