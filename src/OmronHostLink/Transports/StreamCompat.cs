using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>Memory-based stream calls on every target (netstandard2.0 has only the array overloads).</summary>
internal static class StreamCompat
{
    public static ValueTask<int> ReadAsync(Stream stream, Memory<byte> buffer, CancellationToken cancellationToken)
    {
#if NET
        return stream.ReadAsync(buffer, cancellationToken);
#else
        if (!MemoryMarshal.TryGetArray<byte>(buffer, out ArraySegment<byte> segment))
        {
            throw new NotSupportedException("Only array-backed buffers are supported.");
        }

        return new ValueTask<int>(stream.ReadAsync(segment.Array!, segment.Offset, segment.Count, cancellationToken));
#endif
    }

    public static ValueTask WriteAsync(Stream stream, ReadOnlyMemory<byte> buffer, CancellationToken cancellationToken)
    {
#if NET
        return stream.WriteAsync(buffer, cancellationToken);
#else
        if (!MemoryMarshal.TryGetArray(buffer, out ArraySegment<byte> segment))
        {
            segment = new ArraySegment<byte>(buffer.ToArray());
        }

        return new ValueTask(stream.WriteAsync(segment.Array!, segment.Offset, segment.Count, cancellationToken));
#endif
    }

    public static ValueTask DisposeAsync(Stream stream)
    {
#if NET
        return stream.DisposeAsync();
#else
        stream.Dispose();
        return default;
#endif
    }
}
