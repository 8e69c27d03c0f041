using System.Buffers;
using System.Diagnostics;
using System.IO.Pipelines;

namespace OmronHostLink.Testing;

/// <summary>
/// A serial line from a host's port to a PLC in this process, with taps: the host opens <see cref="HostPort"/> (one end
/// of a socat pty pair) as any serial port, the PLC (a simulator) is served on <see cref="PlcStream"/>, and everything
/// either side sends is copied, as it crosses, to a tap port that hears both directions (a half-duplex RS-485 line) and,
/// if asked, to two that hear one direction each (the receive taps of a full-duplex RS-232 line). A monitor listens on
/// the taps. Each tap is a <see cref="PseudoTerminalMaster"/> this process writes to directly: a tap's bytes cross one pty
/// and no other process, so a listener hears them when they crossed, not when a relay process next ran.
/// </summary>
/// <remarks>
/// Both sides' bytes cross at the line's character rate (in batches about a millisecond apart, each holding what the
/// line would have carried by then), so a host that keeps the line busy saturates it. Each side's bytes reach the taps before the other side: the other side may answer
/// at once, and its answer must not reach a tap before what it answers. The PLC's end has no pty and no thread of its
/// own: what the host sends is handed to the PLC on the relay's thread as it crosses, and what the PLC writes goes to the
/// taps and the host in the write itself, so the times a simulator stamps on its frames are the times the bytes crossed.
/// </remarks>
public sealed class TappedSerialLine : IAsyncDisposable
{
    private readonly SocatPtyPair _hostPair;
    private readonly FileStream _hostInner;
    private readonly PseudoTerminalMaster? _tap;
    private readonly PseudoTerminalMaster? _hostTap;
    private readonly PseudoTerminalMaster? _plcTap;
    private readonly object _tapGate = new();
    private readonly double _secondsPerCharacter;
    private readonly Thread _relay;
    private readonly Pipe _toPlc = new(new PipeOptions(readerScheduler: PipeScheduler.Inline, writerScheduler: PipeScheduler.Inline, useSynchronizationContext: false, pauseWriterThreshold: 0));
    private readonly Stopwatch _plcClock = Stopwatch.StartNew();
    private double _plcLineFreeAt;
    private long _bytesToPlc;
    private long _bytesToHost;

    private TappedSerialLine(SocatPtyPair hostPair, int baudRate, int bitsPerCharacter, bool bothDirections, bool eachDirection)
    {
        _hostPair = hostPair;
        _secondsPerCharacter = baudRate > 0 ? (double)bitsPerCharacter / baudRate : 0;
        _hostInner = Open(hostPair.PathB);
        try
        {
            if (bothDirections)
            {
                _tap = PseudoTerminalMaster.Open();
            }

            if (eachDirection)
            {
                _hostTap = PseudoTerminalMaster.Open();
                _plcTap = PseudoTerminalMaster.Open();
            }
        }
        catch
        {
            DisposeTaps();
            _hostInner.Dispose();
            throw;
        }

        PlcStream = new PlcEnd(this);
        _relay = new Thread(RelayFromHost) { IsBackground = true, Name = "line host to PLC" };
    }

    /// <summary>The host's end of the line: a pty to open as a serial port.</summary>
    public string HostPort => _hostPair.PathA;

    /// <summary>The PLC's end of the line, for a simulator to serve (one session).</summary>
    public Stream PlcStream { get; }

    /// <summary>The tap that hears both directions, interleaved as they crossed (null unless asked for).</summary>
    public string? TapPort => _tap?.Path;

    /// <summary>The tap that hears the host only (null unless asked for).</summary>
    public string? HostTapPort => _hostTap?.Path;

    /// <summary>The tap that hears the PLC only (null unless asked for).</summary>
    public string? PlcTapPort => _plcTap?.Path;

    /// <summary>Bytes carried from the host to the PLC so far.</summary>
    public long BytesToPlc => Interlocked.Read(ref _bytesToPlc);

    /// <summary>Bytes carried from the PLC to the host so far.</summary>
    public long BytesToHost => Interlocked.Read(ref _bytesToHost);

    /// <summary>
    /// Makes the line: the host's pty pair, with <paramref name="bothDirections"/> the two-way tap, and with
    /// <paramref name="eachDirection"/> the two one-way taps (a tap nobody reads would fill up and hold the line, so only
    /// those asked for are made). <paramref name="baudRate"/> 0 carries the host's bytes as fast as they come.
    /// </summary>
    public static async Task<TappedSerialLine> StartAsync(int baudRate, int bitsPerCharacter, bool bothDirections = true, bool eachDirection = false)
    {
        SocatPtyPair hostPair = await SocatPtyPair.StartAsync().ConfigureAwait(false);
        TappedSerialLine line;
        try
        {
            line = new TappedSerialLine(hostPair, baudRate, bitsPerCharacter, bothDirections, eachDirection);
        }
        catch
        {
            await hostPair.DisposeAsync().ConfigureAwait(false);
            throw;
        }

        RealTimeScheduling.TryRaise(hostPair.ProcessId);
        line._relay.Start();
        return line;
    }

    /// <summary>
    /// Ends socat (the relay's read ends with it), the relay and the taps, ends the PLC's stream and closes the host's far
    /// end. Idempotent.
    /// </summary>
    public async ValueTask DisposeAsync()
    {
        await _hostPair.CloseAsync().ConfigureAwait(false);

        // A tap whose listener stopped reading may hold the relay in a write: drain the taps until it ends.
        var patience = Stopwatch.StartNew();
        while (!_relay.Join(TimeSpan.FromMilliseconds(10)) && patience.Elapsed < TimeSpan.FromSeconds(5))
        {
            _tap?.Drain();
            _hostTap?.Drain();
            _plcTap?.Drain();
        }

        DisposeTaps();
        await _toPlc.Writer.CompleteAsync().ConfigureAwait(false);
        _hostInner.Dispose();
        await _hostPair.DisposeAsync().ConfigureAwait(false);
    }

    private void DisposeTaps()
    {
        _tap?.Dispose();
        _hostTap?.Dispose();
        _plcTap?.Dispose();
    }

    private static FileStream Open(string path) => new(path, FileMode.Open, FileAccess.ReadWrite, FileShare.ReadWrite, bufferSize: 0);

    /// <summary>Carries the host's bytes to the taps and the PLC at the line's pace.</summary>
    private void RelayFromHost()
    {
        // The PLC's session runs on this thread as bytes reach it (and the simulator's pacing threads start from it).
        RealTimeScheduling.TryRaise();
        var buffer = new byte[4096];
        var clock = Stopwatch.StartNew();
        double lineFreeAt = 0;
        try
        {
            while (true)
            {
                int n = _hostInner.Read(buffer, 0, buffer.Length);
                if (n <= 0)
                {
                    return;
                }

                Pace(buffer.AsSpan(0, n).ToArray(), clock, ref lineFreeAt, bytes =>
                {
                    Tap(bytes, _hostTap);
                    Interlocked.Add(ref _bytesToPlc, bytes.Length);
                    _toPlc.Writer.Write(bytes);
                    _ = _toPlc.Writer.FlushAsync().AsTask().GetAwaiter().GetResult();
                });
            }
        }
        catch (Exception e) when (e is IOException or ObjectDisposedException or InvalidOperationException)
        {
            // socat ended: the line is gone.
        }
    }

    /// <summary>What the PLC writes: at the line's pace, in the write itself, to the taps, then to the host.</summary>
    private void FromPlc(ReadOnlySpan<byte> written)
    {
        Pace(written.ToArray(), _plcClock, ref _plcLineFreeAt, bytes =>
        {
            Tap(bytes, _plcTap);
            Interlocked.Add(ref _bytesToHost, bytes.Length);
            _hostInner.Write(bytes);
        });
    }

    /// <summary>
    /// Hands <paramref name="bytes"/> on at the line's rate: the first character when the line is free, the others in
    /// batches about a millisecond apart, each holding the characters the line would have carried by then.
    /// </summary>
    private void Pace(byte[] bytes, Stopwatch clock, ref double lineFreeAt, Action<byte[]> carry)
    {
        int n = bytes.Length;
        double start = Math.Max(clock.Elapsed.TotalSeconds, lineFreeAt);
        int sent = 0;
        while (sent < n)
        {
            double now = clock.Elapsed.TotalSeconds;
            int due = _secondsPerCharacter == 0 ? n : Math.Min(n, (int)((now - start) / _secondsPerCharacter) + 1);
            if (due > sent)
            {
                carry(bytes[sent..due]);
                sent = due;
                continue;
            }

            Thread.Sleep(1);
        }

        lineFreeAt = start + (n * _secondsPerCharacter);
    }

    private void Tap(ReadOnlySpan<byte> bytes, PseudoTerminalMaster? oneWayTap)
    {
        lock (_tapGate)
        {
            _tap?.Master.Write(bytes);
        }

        oneWayTap?.Master.Write(bytes);
    }

    /// <summary>The PLC's end: reads what the relay hands over (on the relay's thread), writes through to the taps and the host.</summary>
    private sealed class PlcEnd(TappedSerialLine line) : Stream
    {
        private readonly Stream _read = line._toPlc.Reader.AsStream();

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => throw new NotSupportedException();

        public override long Position
        {
            get => throw new NotSupportedException();
            set => throw new NotSupportedException();
        }

        public override void Flush()
        {
        }

        public override Task FlushAsync(CancellationToken cancellationToken) => Task.CompletedTask;

        public override int Read(byte[] buffer, int offset, int count) => _read.Read(buffer, offset, count);

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => _read.ReadAsync(buffer, cancellationToken);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) => _read.ReadAsync(buffer, offset, count, cancellationToken);

        public override void Write(byte[] buffer, int offset, int count) => line.FromPlc(buffer.AsSpan(offset, count));

        public override void Write(ReadOnlySpan<byte> buffer) => line.FromPlc(buffer);

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            line.FromPlc(buffer.Span);
            return ValueTask.CompletedTask;
        }

        public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        {
            line.FromPlc(buffer.AsSpan(offset, count));
            return Task.CompletedTask;
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();
    }
}
