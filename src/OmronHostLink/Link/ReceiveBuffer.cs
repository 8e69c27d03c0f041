using System.Buffers;
using OmronHostLink.Protocol;

namespace OmronHostLink.Link;

/// <summary>
/// The bytes received and not yet taken: appended by the frame channel's receive loop, taken as a frame (noise before
/// it dropped) or as the line's echo of what was sent, and discarded by a resynchronisation. Not thread-safe: the
/// channel holds its lock around every call.
/// </summary>
internal sealed class ReceiveBuffer
{
    private byte[] _bytes = new byte[4096];
    private int _start;
    private int _end;

    /// <summary>Bytes held.</summary>
    public int Held => _end - _start;

    /// <summary>Appends received bytes, growing the buffer when what is held and the new bytes do not fit.</summary>
    public void Append(ReadOnlySpan<byte> received)
    {
        if (_end + received.Length > _bytes.Length)
        {
            int held = Held;
            if (held + received.Length > _bytes.Length)
            {
                Array.Resize(ref _bytes, Math.Max(_bytes.Length * 2, held + received.Length));
            }

            Buffer.BlockCopy(_bytes, _start, _bytes, 0, held);
            _start = 0;
            _end = held;
        }

        received.CopyTo(_bytes.AsSpan(_end));
        _end += received.Length;
    }

    /// <summary>Takes the first complete frame into <paramref name="frame"/>, dropping noise before it.</summary>
    /// <param name="expectStart">True where a frame starts with <c>@</c> (what comes before it is noise).</param>
    /// <param name="frame">Receives the frame, CR included.</param>
    /// <param name="error">Set (and everything held dropped) when more than <see cref="FrameReader.MaxFrameLength"/> characters came without a CR.</param>
    /// <returns>The frame's length, or 0 when no frame is complete yet (or on <paramref name="error"/>).</returns>
    public int TakeFrame(bool expectStart, Span<byte> frame, out Exception? error)
    {
        error = null;
        int held = Held;
        var buffer = new ReadOnlySequence<byte>(_bytes, _start, held);
        FrameScanResult scan = FrameReader.TryReadFrame(ref buffer, expectStart, out ReadOnlySequence<byte> found, out _);
        if (scan == FrameScanResult.Overflow)
        {
            Clear();
            error = new HostLinkFrameException(FrameError.TooLong, $"More than {FrameReader.MaxFrameLength} characters arrived without a CR.");
            return 0;
        }

        // Taken: the frame, or the noise skipped before a frame's start, which is gone for good.
        Consume(held - (int)buffer.Length);
        if (scan != FrameScanResult.Frame)
        {
            return 0;
        }

        found.CopyTo(frame);
        return (int)found.Length;
    }

    /// <summary>Takes the echo of <paramref name="sent"/> once all of it is held, and checks it.</summary>
    /// <returns>The echo's length, or 0 when not all of it is in yet (or on <paramref name="error"/>: it differs).</returns>
    public int TakeEcho(ReadOnlySpan<byte> sent, out Exception? error)
    {
        error = null;
        if (Held < sent.Length)
        {
            return 0;
        }

        if (!_bytes.AsSpan(_start, sent.Length).SequenceEqual(sent))
        {
            error = new HostLinkFrameException(FrameError.Unexpected, "The line's echo of our frame differs from what was sent.");
        }

        Consume(sent.Length);
        return error is null ? sent.Length : 0;
    }

    /// <summary>What is held.</summary>
    public ReadOnlySpan<byte> HeldBytes => _bytes.AsSpan(_start, Held);

    /// <summary>Whether a frame starts (<c>@</c>) in what is held.</summary>
    public bool HoldsFrameStart() => _bytes.AsSpan(_start, Held).IndexOf((byte)'@') >= 0;

    /// <summary>Drops everything held.</summary>
    /// <returns>The number of bytes dropped.</returns>
    public int Clear()
    {
        int dropped = Held;
        _start = _end = 0;
        return dropped;
    }

    private void Consume(int count)
    {
        _start += count;
        if (_start == _end)
        {
            _start = _end = 0;
        }
    }
}
