using System.Buffers;
using System.IO.Pipelines;
using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// A serial cable from a host's port to a simulated PLC's port, each set to its own speed and format, in memory: what the
/// host sends reaches the PLC as the PLC's UART would receive it (<see cref="UartModel"/>), and the answers come back the
/// same way, so a host at other settings than the PLC's port gets the garbage, the changed characters and the silence a
/// real line gives. The PLC's port ignores a frame in which its UART found a parity or framing error, as a CS/CJ does
/// (W342: no response to parity, framing or overrun errors). With <see cref="TwoWireEcho"/> the host also hears its own
/// transmission, as on a 2-wire RS-485 adapter without echo suppression.
/// </summary>
/// <remarks>
/// Each <see cref="Open"/> is one opening of the host's port at the settings it asks for: a stream for the host and a
/// session of the PLCs on the other end, ended when the host closes its port. A pseudo-terminal cannot show any of this:
/// it carries bytes whatever its baud rate and parity say.
/// </remarks>
internal sealed class EmulatedSerialLine
{
    private const int PortBufferLength = 1200;

    private readonly VirtualPlcLine _plcs;
    private readonly object _gate = new();
    private readonly List<(SerialLineSettings Settings, byte[] Bytes)> _sent = new();

    /// <summary>Puts the PLCs on the far end of a line whose PLC port has <paramref name="plcPort"/>'s settings.</summary>
    public EmulatedSerialLine(VirtualPlcLine plcs, SerialLineSettings plcPort, bool twoWireEcho = false)
    {
        ArgumentNullException.ThrowIfNull(plcs);
        ArgumentNullException.ThrowIfNull(plcPort);
        _plcs = plcs;
        PlcPort = plcPort.Clone();
        TwoWireEcho = twoWireEcho;
    }

    /// <summary>The PLC port's settings.</summary>
    public SerialLineSettings PlcPort { get; }

    /// <summary>Whether the host hears its own transmission.</summary>
    public bool TwoWireEcho { get; }

    /// <summary>Every write the host made, with the settings its port had: what it put on the line, read at its own settings.</summary>
    public IReadOnlyList<(SerialLineSettings Settings, byte[] Bytes)> HostTransmissions
    {
        get
        {
            lock (_gate)
            {
                return _sent.ToArray();
            }
        }
    }

    /// <summary>Frames the PLC port ignored because its UART found an error in them.</summary>
    public int FramesWithLineErrors { get; private set; }

    /// <summary>How often the host opened its port.</summary>
    public int Openings { get; private set; }

    /// <summary>A transport for the host's port at <paramref name="host"/>'s settings (opened on first use, as a serial port is).</summary>
    public IHostLinkTransport Transport(SerialLineSettings host) => new HostPort(this, host.Clone());

    /// <summary>Opens the host's port at <paramref name="host"/>'s settings and starts a session of the PLCs on the far end.</summary>
    /// <returns>The host's end, and a task that ends with the session when the host closes its end.</returns>
    public (Stream HostEnd, Task Session) Open(SerialLineSettings host)
    {
        var toPlc = new Pipe(new PipeOptions(useSynchronizationContext: false));
        var toHost = new Pipe(new PipeOptions(useSynchronizationContext: false));
        var hostSide = new Side(toHost.Writer);
        var plcPortReceiver = new PortReceiver(this, toPlc.Writer);
        var hostEnd = new End(toHost.Reader, bytes =>
        {
            lock (_gate)
            {
                _sent.Add((host, bytes.ToArray()));
            }

            if (TwoWireEcho)
            {
                hostSide.Write(bytes);
            }

            plcPortReceiver.Take(UartModel.Transfer(bytes, host, PlcPort));
        });
        var plcEnd = new End(toPlc.Reader, bytes =>
        {
            // The host's UART passes on what it took, errors and all: System.IO.Ports reports no parity errors.
            List<UartModel.Received> taken = UartModel.Transfer(bytes, PlcPort, host);
            var data = new byte[taken.Count];
            for (int i = 0; i < data.Length; i++)
            {
                data[i] = taken[i].Value;
            }

            hostSide.Write(data);
        });
        hostEnd.Closed += () =>
        {
            toPlc.Writer.Complete();
            toHost.Reader.Complete();
        };
        plcEnd.Closed += () =>
        {
            toHost.Writer.Complete();
            toPlc.Reader.Complete();
        };
        lock (_gate)
        {
            Openings++;
        }

        Task session = _plcs.RunAsync(plcEnd);
        return (hostEnd, session);
    }

    /// <summary>One writer of the host's receive pipe, shared by the echo and the PLC's answers.</summary>
    private sealed class Side(PipeWriter writer)
    {
        private readonly object _gate = new();

        public void Write(ReadOnlySpan<byte> bytes)
        {
            lock (_gate)
            {
                try
                {
                    writer.Write((ReadOnlySpan<byte>)bytes);
                    writer.FlushAsync().AsTask().GetAwaiter().GetResult();
                }
                catch (InvalidOperationException)
                {
                    // The host closed its port: nobody hears the line now.
                }
            }
        }
    }

    /// <summary>The PLC port's receiver: frames in which its UART found an error are dropped at their CR.</summary>
    private sealed class PortReceiver(EmulatedSerialLine line, PipeWriter toPlc)
    {
        private readonly object _gate = new();
        private readonly List<byte> _frame = new();
        private bool _damaged;

        public void Take(List<UartModel.Received> characters)
        {
            lock (_gate)
            {
                foreach (UartModel.Received c in characters)
                {
                    _frame.Add(c.Value);
                    _damaged |= c.Error;
                    if (c.Value == (byte)'\r' || _frame.Count > PortBufferLength)
                    {
                        if (_damaged)
                        {
                            line.FramesWithLineErrors++;
                        }
                        else if (c.Value == (byte)'\r')
                        {
                            try
                            {
                                toPlc.Write((ReadOnlySpan<byte>)_frame.ToArray());
                                toPlc.FlushAsync().AsTask().GetAwaiter().GetResult();
                            }
                            catch (InvalidOperationException)
                            {
                            }
                        }

                        _frame.Clear();
                        _damaged = false;
                    }
                }
            }
        }
    }

    /// <summary>One end of the cable: reads what reached it, hands what it writes to the line.</summary>
    private sealed class End(PipeReader reader, Action<byte[]> send) : Stream
    {
        private readonly Stream _read = reader.AsStream(leaveOpen: true);
        private int _closed;

        public event Action? Closed;

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

        public override void Write(byte[] buffer, int offset, int count) => Send(buffer.AsSpan(offset, count));

        public override void Write(ReadOnlySpan<byte> buffer) => Send(buffer);

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            cancellationToken.ThrowIfCancellationRequested();
            Send(buffer.Span);
            return ValueTask.CompletedTask;
        }

        public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        {
            cancellationToken.ThrowIfCancellationRequested();
            Send(buffer.AsSpan(offset, count));
            return Task.CompletedTask;
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing && Interlocked.Exchange(ref _closed, 1) == 0)
            {
                Closed?.Invoke();
                reader.CancelPendingRead();
            }

            base.Dispose(disposing);
        }

        private void Send(ReadOnlySpan<byte> bytes)
        {
            if (Volatile.Read(ref _closed) != 0)
            {
                throw new ObjectDisposedException(nameof(EmulatedSerialLine), "The port is closed.");
            }

            send(bytes.ToArray());
        }
    }

    /// <summary>The host's port on this line, at the settings it was made with.</summary>
    private sealed class HostPort(EmulatedSerialLine line, SerialLineSettings settings) : IHostLinkTransport
    {
        private Stream? _stream;
        private Task? _session;

        public string Description => settings.ToString();

        public LineTiming? LineTiming { get; } = new(settings.BaudRate, settings.BitsPerCharacter);

        public ValueTask<Stream> OpenAsync(CancellationToken cancellationToken)
        {
            cancellationToken.ThrowIfCancellationRequested();
            if (_stream is null)
            {
                (_stream, _session) = line.Open(settings);
            }

            return new ValueTask<Stream>(_stream);
        }

        public async ValueTask CloseAsync()
        {
            Stream? stream = Interlocked.Exchange(ref _stream, null);
            if (stream is not null)
            {
                await stream.DisposeAsync().ConfigureAwait(false);
                await _session!.ConfigureAwait(false);
            }
        }

        public ValueTask DisposeAsync() => CloseAsync();
    }
}
