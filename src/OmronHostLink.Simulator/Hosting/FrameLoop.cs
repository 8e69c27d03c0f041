using System.Buffers;
using System.IO.Pipelines;
using OmronHostLink.Protocol;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// The PLC side's reading of a line: the frames cut out of a stream's bytes (noise before <c>@</c> skipped while a
/// first frame is due), each handed on with the time the read that completed it returned, until the stream ends, the
/// line goes away or the session is stopped. A run without a CR longer than a unit's reception buffer is dropped, as a
/// unit drops it.
/// </summary>
internal static class FrameLoop
{
    /// <summary>Serves <paramref name="stream"/> until it ends; never faulted by line errors or a closed stream.</summary>
    /// <param name="stream">The PLC's end of the line; not disposed.</param>
    /// <param name="expectsFirstFrame">Whether the next frame must start with <c>@</c> (no exchange in progress).</param>
    /// <param name="onFrame">Takes each frame (CR included) and the time it arrived.</param>
    /// <param name="onOverflow">Told when a run without a CR was dropped: any exchange in progress is over.</param>
    /// <param name="cancellationToken">Stops the session.</param>
    public static async Task RunAsync(Stream stream, Func<bool> expectsFirstFrame, Func<byte[], DateTimeOffset, Task> onFrame, Action onOverflow, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(stream);
        PipeReader reader = PipeReader.Create(stream, new StreamPipeReaderOptions(leaveOpen: true));
        try
        {
            while (true)
            {
                ReadResult result = await reader.ReadAsync(cancellationToken).ConfigureAwait(false);
                DateTimeOffset arrived = DateTimeOffset.UtcNow;
                ReadOnlySequence<byte> buffer = result.Buffer;
                while (true)
                {
                    FrameScanResult scan = FrameReader.TryReadFrame(ref buffer, expectsFirstFrame(), out ReadOnlySequence<byte> frame, out _);
                    if (scan == FrameScanResult.NeedMoreData)
                    {
                        break;
                    }

                    if (scan == FrameScanResult.Overflow)
                    {
                        // No CR within the reception buffer: a real unit discards it silently and starts over.
                        onOverflow();
                        if (buffer.Length > FrameReader.MaxFrameLength)
                        {
                            buffer = buffer.Slice(buffer.End);
                        }

                        continue;
                    }

                    await onFrame(frame.ToArray(), arrived).ConfigureAwait(false);
                }

                reader.AdvanceTo(buffer.Start, buffer.End);
                if (result.IsCompleted || result.IsCanceled)
                {
                    return;
                }
            }
        }
        catch (OperationCanceledException) when (cancellationToken.IsCancellationRequested)
        {
            // The session was stopped.
        }
        catch (IOException)
        {
            // The line went away.
        }
        catch (ObjectDisposedException)
        {
            // The stream was closed under us.
        }
        finally
        {
            await reader.CompleteAsync().ConfigureAwait(false);
        }
    }
}
