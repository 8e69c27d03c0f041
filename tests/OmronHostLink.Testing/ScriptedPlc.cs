using System.Collections.Concurrent;
using System.Text;

namespace OmronHostLink.Testing;

/// <summary>What a scripted PLC sends back for one received frame.</summary>
public sealed record Reply(string Text, TimeSpan Delay = default, int ChunkSize = 0)
{
    public static Reply None { get; } = new(string.Empty);
}

/// <summary>
/// A PLC played by a test: it reads CR-terminated frames from its end of the link and answers each with whatever the
/// handler returns. TS frames are echoed (as a PLC does) unless the handler answers them; every received frame is logged.
/// </summary>
public sealed class ScriptedPlc : IAsyncDisposable
{
    private readonly Stream _stream;
    private readonly Func<string, Reply?> _handler;
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;
    private readonly Random _random = new(1234);

    public ScriptedPlc(Stream plcEnd, Func<string, Reply?> handler)
    {
        _stream = plcEnd;
        _handler = handler;
        _loop = Task.Run(RunAsync);
    }

    public ConcurrentQueue<string> Received { get; } = new();

    /// <summary>The clock a <see cref="Reply.Delay"/> is kept on. Default the system's.</summary>
    public TimeProvider Time { get; init; } = TimeProvider.System;

    public int ReceivedCount(Func<string, bool> predicate) => Received.Count(predicate);

    private async Task RunAsync()
    {
        var line = new StringBuilder();
        var buffer = new byte[1];
        try
        {
            while (!_stop.IsCancellationRequested)
            {
                int n = await _stream.ReadAsync(buffer, _stop.Token);
                if (n == 0)
                {
                    return;
                }

                line.Append((char)buffer[0]);
                if (buffer[0] != '\r')
                {
                    continue;
                }

                string frame = line.ToString();
                line.Clear();
                Received.Enqueue(frame);
                Reply? reply = _handler(frame);
                if (reply is null && frame.Length > 5 && frame.Substring(3, 2) == "TS")
                {
                    reply = new Reply(frame);
                }

                if (reply is null || reply.Text.Length == 0)
                {
                    continue;
                }

                if (reply.Delay > TimeSpan.Zero)
                {
                    // A late answer (the emulated PLC's latency, on its clock): later frames wait in the link meanwhile,
                    // so answers stay in order as on a real line.
                    await Task.Delay(reply.Delay, Time, _stop.Token);
                }

                await SendAsync(reply);
            }
        }
        catch (OperationCanceledException)
        {
        }
        catch (IOException)
        {
        }
        catch (InvalidOperationException)
        {
            // The far end closed the in-memory link under a pending read.
        }
    }

    private async Task SendAsync(Reply reply)
    {
        byte[] bytes = Encoding.ASCII.GetBytes(reply.Text);
        if (reply.ChunkSize == 0)
        {
            await _stream.WriteAsync(bytes, _stop.Token);
            return;
        }

        int i = 0;
        while (i < bytes.Length)
        {
            int size = reply.ChunkSize > 0 ? reply.ChunkSize : _random.Next(1, 9);
            size = Math.Min(size, bytes.Length - i);
            await _stream.WriteAsync(bytes.AsMemory(i, size), _stop.Token);
            i += size;
            await Task.Yield();
        }
    }

    public async ValueTask DisposeAsync()
    {
        // The loop ends on the cancellation before the stream goes: a read racing the stream's disposal fails untyped.
        _stop.Cancel();
        try
        {
            await _loop;
        }
        catch (OperationCanceledException)
        {
        }

        await _stream.DisposeAsync();
    }
}
