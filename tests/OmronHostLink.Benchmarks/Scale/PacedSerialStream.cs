using System.Diagnostics;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// The serial side of an emulated serial-device server, wrapped around the PLC's end of a TCP connection: bytes from
/// the host reach the PLC when their last stop bit would have arrived, and the PLC's answer leaves when its last
/// character would have been sent, each direction N × bits / baud per N characters, one character at a time on the
/// line. Counts the characters both ways, and samples two delays: how late the pacing timers fired, and the host's
/// gap — from the end of an answer to the arrival of the host's next command (loopback both ways, the host's own work
/// between two transactions, and any idle wait for its next poll).
/// </summary>
/// <remarks>
/// Timed by a shared <see cref="LineClock"/> (a few tenths of a millisecond), not by the simulator's own pacer, which
/// spins on a thread of its own for the last character of every frame to be exact to microseconds: at a thousand
/// frames a second that spinning alone would take most of a core from the processes being measured. A late wake-up
/// only lengthens a transaction, so the figures err on the slow side.
/// </remarks>
internal sealed class PacedSerialStream(Stream inner, int baudRate, int bitsPerCharacter, LineClock clock) : PassThroughStream(inner)
{
    private readonly double _ticksPerCharacter = (double)bitsPerCharacter / baudRate * Stopwatch.Frequency;
    private long _inboundFreeAt;
    private long _outboundFreeAt;
    private long _charactersIn;
    private long _charactersOut;
    private long _answerSentAt;
    private readonly List<double> _gapsMs = new();
    private readonly List<double> _latenessMs = new();

    /// <summary>Characters the host sent (commands and the CR delimiters between frames).</summary>
    public long CharactersIn => Interlocked.Read(ref _charactersIn);

    /// <summary>Characters the PLC sent (answers).</summary>
    public long CharactersOut => Interlocked.Read(ref _charactersOut);

    /// <summary>Takes the samples gathered since the last call.</summary>
    public (double[] GapsMs, double[] LatenessMs) TakeSamples()
    {
        lock (_gapsMs)
        {
            var taken = (_gapsMs.ToArray(), _latenessMs.ToArray());
            _gapsMs.Clear();
            _latenessMs.Clear();
            return taken;
        }
    }

    public override async ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default)
    {
        int n = await Inner.ReadAsync(buffer, cancellationToken).ConfigureAwait(false);
        if (n > 0)
        {
            // The host's bytes left it just now; on the line they follow whatever is still arriving.
            long arrived = Stopwatch.GetTimestamp();
            if (_answerSentAt != 0)
            {
                Sample(_gapsMs, arrived - _answerSentAt);
                _answerSentAt = 0;
            }

            _inboundFreeAt = Math.Max(arrived, _inboundFreeAt) + (long)(n * _ticksPerCharacter);
            await WaitUntilAsync(_inboundFreeAt, cancellationToken).ConfigureAwait(false);
            Interlocked.Add(ref _charactersIn, n);
        }

        return n;
    }

    public override async ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
    {
        _outboundFreeAt = Math.Max(Stopwatch.GetTimestamp(), _outboundFreeAt) + (long)(buffer.Length * _ticksPerCharacter);
        await WaitUntilAsync(_outboundFreeAt, cancellationToken).ConfigureAwait(false);
        // Stamped before the send: the send wakes the host, which on a busy machine may run (and answer) before this
        // thread runs again.
        _answerSentAt = Stopwatch.GetTimestamp();
        await Inner.WriteAsync(buffer, cancellationToken).ConfigureAwait(false);
        Interlocked.Add(ref _charactersOut, buffer.Length);
    }

    private async Task WaitUntilAsync(long timestamp, CancellationToken cancellationToken)
    {
        await clock.WaitUntilAsync(timestamp, cancellationToken).ConfigureAwait(false);
        Sample(_latenessMs, Stopwatch.GetTimestamp() - timestamp);
    }

    private void Sample(List<double> samples, long ticks)
    {
        lock (_gapsMs)
        {
            // Bounded: a benchmark window takes its samples long before this many accumulate.
            if (samples.Count < 1_000_000)
            {
                samples.Add(ticks * 1000.0 / Stopwatch.Frequency);
            }
        }
    }
}
