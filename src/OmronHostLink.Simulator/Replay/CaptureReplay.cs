using OmronHostLink.Capture;
using OmronHostLink.Protocol;
using OmronHostLink.Protocol.CMode;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Simulator.Replay;

/// <summary>
/// A PLC that answers as a recorded one did: each command found in a capture (a pcap written by <c>hostlink
/// monitor-line</c>, a client's trace file or the simulator) gets the answer the PLC gave it there, the first time the
/// first answer, the next time the next, and the last one again once they are used up. TS is echoed whatever the capture
/// holds, as every PLC does. A divided command is taken frame by frame with the CR a PLC sends between frames; a divided
/// answer is sent frame by frame on the host's CR. An FA answer carries the service ID of the command it answers.
/// </summary>
/// <remarks>A command the capture does not hold gets no answer (a real PLC's answer cannot be made up); <see cref="Unmatched"/> counts them.</remarks>
public sealed class CaptureReplay
{
    private readonly RecordedExchanges _recorded;
    private readonly Dictionary<string, int> _served = new(StringComparer.Ordinal);
    private readonly object _gate = new();
    private long _unmatched;

    private CaptureReplay(RecordedExchanges recorded, string name)
    {
        _recorded = recorded;
        Name = name;
    }

    /// <summary>The capture's file name.</summary>
    public string Name { get; }

    /// <summary>How many exchanges the capture holds.</summary>
    public int Exchanges => _recorded.Count;

    /// <summary>The unit numbers that answered in the capture.</summary>
    public IReadOnlyCollection<int> Units => _recorded.Units;

    /// <summary>The line speed whose wire time each answer takes (0, the default: answers go as fast as the stream takes them).</summary>
    public int BaudRate { get; init; }

    /// <summary>Bits on the line per character, for <see cref="BaudRate"/>. Default 11 (7E2).</summary>
    public int BitsPerCharacter { get; init; } = 11;

    /// <summary>Told, in a sentence, of each command the capture does not hold; may be null.</summary>
    public Action<string>? Report { get; init; }

    /// <summary>Commands received that the capture does not hold (so went unanswered).</summary>
    public long Unmatched => Interlocked.Read(ref _unmatched);

    /// <summary>Reads a capture file (pcap or pcapng of Host Link records).</summary>
    /// <param name="path">The file.</param>
    /// <param name="baudRate">The line speed whose wire time answers take, or 0.</param>
    /// <param name="bitsPerCharacter">Bits per character for <paramref name="baudRate"/>.</param>
    /// <param name="report">Told of each command the capture does not hold; may be null.</param>
    /// <returns>The replay.</returns>
    /// <exception cref="FormatException">The file is not a Host Link capture, or holds no exchange; the message says why.</exception>
    /// <exception cref="IOException">The file cannot be read.</exception>
    public static CaptureReplay Load(string path, int baudRate = 0, int bitsPerCharacter = 11, Action<string>? report = null)
    {
        ArgumentNullException.ThrowIfNull(path);
        RecordedExchanges recorded = RecordedExchanges.From(CaptureReader.Read(path));
        if (recorded.Count == 0)
        {
            throw new FormatException($"{Path.GetFileName(path)} holds no command with its answer to replay.");
        }

        return new CaptureReplay(recorded, Path.GetFileName(path)) { BaudRate = baudRate, BitsPerCharacter = bitsPerCharacter, Report = report };
    }

    /// <summary>Serves one session over <paramref name="stream"/> until it ends or <paramref name="cancellationToken"/> is cancelled.</summary>
    /// <param name="stream">The PLC's end of a line.</param>
    /// <param name="cancellationToken">Ends the session.</param>
    /// <returns>A task that completes when the session ends (never faulted by line errors or a closed stream).</returns>
    public Task RunAsync(Stream stream, CancellationToken cancellationToken = default)
    {
        ArgumentNullException.ThrowIfNull(stream);
        var session = new Session(this, stream, new WirePacer(BaudRate, BitsPerCharacter), cancellationToken);
        return FrameLoop.RunAsync(stream, session.ExpectsFirstFrame, session.TakeAsync, session.Reset, cancellationToken);
    }

    /// <summary>The answer to <paramref name="command"/>: the next one recorded for it, an echo for TS, or null.</summary>
    private byte[][]? Answer(List<byte[]> command)
    {
        IReadOnlyList<byte[][]>? answers = _recorded.AnswersTo(command);
        if (answers is null)
        {
            if (command.Count == 1 && RecordedExchanges.IsTest(command[0]))
            {
                return [command[0]];
            }

            Interlocked.Increment(ref _unmatched);
            Report?.Invoke($"Not in {Name}, so not answered: {FrameText.Printable(command[0])}{(command.Count > 1 ? $" (+{command.Count - 1} frames)" : "")}");
            return null;
        }

        string key = RecordedExchanges.Key(command);
        int index;
        lock (_gate)
        {
            _served.TryGetValue(key, out index);
            _served[key] = index + 1;
        }

        byte[][] recorded = answers[Math.Min(index, answers.Count - 1)];
        return WithServiceId(recorded, command[0]);
    }

    /// <summary>An FA answer with the service ID of the command it answers now (its FCS made again).</summary>
    private static byte[][] WithServiceId(byte[][] answer, byte[] command)
    {
        if (RecordedExchanges.FinsServiceIdAt(command, answer: false) is not int from
            || RecordedExchanges.FinsServiceIdAt(answer[0], answer: true) is not int to
            || answer[0].AsSpan(to, 2).SequenceEqual(command.AsSpan(from, 2)))
        {
            return answer;
        }

        byte[] first = (byte[])answer[0].Clone();
        command.AsSpan(from, 2).CopyTo(first.AsSpan(to, 2));
        FrameCheck check = FrameCheck.Of(first);
        if (check.FcsAt >= 0)
        {
            Fcs.Write(first.AsSpan(0, check.FcsAt), first.AsSpan(check.FcsAt, 2));
        }

        return [first, .. answer.Skip(1)];
    }

    /// <summary>One session's state: a divided command being received, or a divided answer being sent.</summary>
    private sealed class Session(CaptureReplay replay, Stream stream, WirePacer pacer, CancellationToken cancellationToken)
    {
        private readonly List<byte[]> _command = new();
        private Queue<byte[]>? _answer;

        public bool ExpectsFirstFrame() => _command.Count == 0 && _answer is null;

        public void Reset()
        {
            _command.Clear();
            _answer = null;
        }

        public async Task TakeAsync(byte[] frame, DateTimeOffset arrived)
        {
            bool first = frame[0] == (byte)'@';
            if (CModeFrames.IsInitialize(frame))
            {
                Reset();
                return;
            }

            if (_answer is not null)
            {
                if (first && IsAbort(frame))
                {
                    _answer = null;
                    return;
                }

                // The host's CR (or, as the manuals allow, another command) asks for the next frame.
                await pacer.WriteAsync(stream, _answer.Dequeue(), cancellationToken).ConfigureAwait(false);
                if (_answer.Count == 0)
                {
                    _answer = null;
                }

                return;
            }

            if (first)
            {
                _command.Clear();
            }
            else if (_command.Count == 0)
            {
                return;
            }

            _command.Add(frame);
            if (!FrameCheck.Of(frame).IsFinal)
            {
                await pacer.WriteAsync(stream, "\r"u8.ToArray(), cancellationToken).ConfigureAwait(false);
                return;
            }

            byte[][]? reply = replay.Answer(_command);
            _command.Clear();
            if (reply is null)
            {
                return;
            }

            await pacer.WriteAsync(stream, reply[0], cancellationToken).ConfigureAwait(false);
            if (reply.Length > 1)
            {
                _answer = new Queue<byte[]>(reply.Skip(1));
            }
        }
    }

    private static bool IsAbort(byte[] frame) => frame.Length >= 5 && CModeHeaders.Is(frame.AsSpan(3, 2), CModeCommands.Abort.Header);
}
