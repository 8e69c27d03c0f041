using System.Buffers;

namespace OmronHostLink.Tests.Infrastructure;

/// <summary>Builds a ReadOnlySequence cut into the given pieces, to test parsing across segment boundaries.</summary>
internal sealed class Segments : ReadOnlySequenceSegment<byte>
{
    private Segments(ReadOnlyMemory<byte> memory, long runningIndex)
    {
        Memory = memory;
        RunningIndex = runningIndex;
    }

    public static ReadOnlySequence<byte> Cut(byte[] bytes, Random random)
    {
        var first = new Segments(Array.Empty<byte>(), 0);
        Segments last = first;
        int i = 0;
        while (i < bytes.Length)
        {
            int n = Math.Min(random.Next(1, 12), bytes.Length - i);
            var next = new Segments(bytes.AsMemory(i, n), last.RunningIndex + last.Memory.Length);
            last.Next = next;
            last = next;
            i += n;
        }

        return new ReadOnlySequence<byte>(first, 0, last, last.Memory.Length);
    }
}
