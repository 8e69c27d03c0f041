using System.Text;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// A client (with <c>Model</c> and <c>HostLinkCompatibleMode</c> set as given) on an in-memory line to a simulated PLC,
/// counting the bytes it sends and keeping the frames it sent, so a test can show that nothing was sent, or what was.
/// </summary>
internal sealed class EmulatedLine : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly CountingStream _host;
    private readonly Task _session;
    private readonly List<string> _sent = [];

    private EmulatedLine(VirtualPlc plc, string? model, HostLinkCompatibleMode? compatibleMode, Action<HostLinkClientOptions>? configure)
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _host = new CountingStream(host);
        _session = plc.RunAsync(plcEnd, _stop.Token);
        var options = new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = InProcessLine.InMemoryAllowance,
            Model = model,
            HostLinkCompatibleMode = compatibleMode,
        };
        configure?.Invoke(options);
        Client = HostLinkClient.ForStream(_host, options);
        Client.FrameObserver = (sent, frame) =>
        {
            if (sent)
            {
                lock (_sent)
                {
                    _sent.Add(Encoding.ASCII.GetString(frame.Span));
                }
            }
        };
    }

    public HostLinkClient Client { get; }

    public long BytesSent => _host.Written;

    /// <summary>The frames the client has sent, as text.</summary>
    public IReadOnlyList<string> SentFrames
    {
        get
        {
            lock (_sent)
            {
                return [.. _sent];
            }
        }
    }

    public static EmulatedLine Start(VirtualPlc plc, string? model, HostLinkCompatibleMode? compatibleMode = null, Action<HostLinkClientOptions>? configure = null)
        => new(plc, model, compatibleMode, configure);

    public async ValueTask DisposeAsync()
    {
        await Client.DisposeAsync();
        _stop.Cancel();
        await _session;
        _stop.Dispose();
    }

    private sealed class CountingStream(Stream inner) : Stream
    {
        private long _written;

        public long Written => Interlocked.Read(ref _written);

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => throw new NotSupportedException();

        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }

        public override void Flush() => inner.Flush();

        public override Task FlushAsync(CancellationToken cancellationToken) => inner.FlushAsync(cancellationToken);

        public override int Read(byte[] buffer, int offset, int count) => inner.Read(buffer, offset, count);

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => inner.ReadAsync(buffer, cancellationToken);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) => inner.ReadAsync(buffer, offset, count, cancellationToken);

        public override void Write(byte[] buffer, int offset, int count)
        {
            Interlocked.Add(ref _written, count);
            inner.Write(buffer, offset, count);
        }

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default)
        {
            Interlocked.Add(ref _written, buffer.Length);
            return inner.WriteAsync(buffer, cancellationToken);
        }

        public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken)
        {
            Interlocked.Add(ref _written, count);
            return inner.WriteAsync(buffer, offset, count, cancellationToken);
        }

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing)
            {
                inner.Dispose();
            }

            base.Dispose(disposing);
        }
    }
}
