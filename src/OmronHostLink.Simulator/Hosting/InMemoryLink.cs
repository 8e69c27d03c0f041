using System.IO.Pipelines;

namespace OmronHostLink.Simulator.Hosting;

/// <summary>
/// A pair of connected in-process streams, like the two ends of a serial cable: what one end writes the other reads.
/// Tests and demos put the client on one end and a PLC (simulated or scripted) on the other.
/// </summary>
public static class InMemoryLink
{
    /// <summary>Creates the two ends.</summary>
    public static (Stream HostEnd, Stream PlcEnd) CreatePair()
    {
        var toPlc = new Pipe(new PipeOptions(useSynchronizationContext: false));
        var toHost = new Pipe(new PipeOptions(useSynchronizationContext: false));
        return (new DuplexPipeStream(toHost.Reader, toPlc.Writer), new DuplexPipeStream(toPlc.Reader, toHost.Writer));
    }

    /// <summary>One end: reads from one pipe, writes to the other. Disposing it completes both, so the far end sees end of stream.</summary>
    private sealed class DuplexPipeStream(PipeReader reader, PipeWriter writer) : Stream
    {
        private readonly Stream _read = reader.AsStream();
        private readonly Stream _write = writer.AsStream();

        public override bool CanRead => true;

        public override bool CanSeek => false;

        public override bool CanWrite => true;

        public override long Length => throw new NotSupportedException();

        public override long Position
        {
            get => throw new NotSupportedException();
            set => throw new NotSupportedException();
        }

        public override void Flush() => _write.Flush();

        public override Task FlushAsync(CancellationToken cancellationToken) => _write.FlushAsync(cancellationToken);

        public override int Read(byte[] buffer, int offset, int count) => _read.Read(buffer, offset, count);

        public override ValueTask<int> ReadAsync(Memory<byte> buffer, CancellationToken cancellationToken = default) => _read.ReadAsync(buffer, cancellationToken);

        public override Task<int> ReadAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) => _read.ReadAsync(buffer, offset, count, cancellationToken);

        public override void Write(byte[] buffer, int offset, int count) => _write.Write(buffer, offset, count);

        public override ValueTask WriteAsync(ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken = default) => _write.WriteAsync(buffer, cancellationToken);

        public override Task WriteAsync(byte[] buffer, int offset, int count, CancellationToken cancellationToken) => _write.WriteAsync(buffer, offset, count, cancellationToken);

        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();

        public override void SetLength(long value) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing)
            {
                reader.Complete();
                writer.Complete();
            }

            base.Dispose(disposing);
        }
    }
}
