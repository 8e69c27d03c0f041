using OmronHostLink.Capture;
using OmronHostLink.Protocol;

namespace OmronHostLink.Simulator;

/// <summary>One frame on a simulated line: received from the host, or sent by the simulated PLCs.</summary>
public sealed class SimulatorFrame
{
    internal SimulatorFrame(bool fromHost, DateTimeOffset firstByteTime, DateTimeOffset time, byte[] bytes, bool framed)
    {
        FromHost = fromHost;
        FirstByteTime = firstByteTime;
        Time = time;
        Bytes = bytes;
        IsFrame = framed;
    }

    /// <summary>True for what the PLCs received from the host; false for what they (or, with echo faults, the line) sent.</summary>
    public bool FromHost { get; }

    /// <summary>
    /// When the frame's last byte crossed the line: for a received frame, when the read that brought its CR returned; for a
    /// sent one, when its last byte was handed to the stream (at the emulated wire speed, when its last stop bit ended).
    /// </summary>
    public DateTimeOffset Time { get; }

    /// <summary>When its first byte did: for a sent frame, when it was handed to the stream; for a received one, <see cref="Time"/>.</summary>
    public DateTimeOffset FirstByteTime { get; }

    /// <summary>The bytes, CR included.</summary>
    public ReadOnlyMemory<byte> Bytes { get; }

    /// <summary>False for bytes that are not a frame: injected noise, a frame cut short.</summary>
    public bool IsFrame { get; }

    /// <summary>The unit number of a first frame (<c>@</c> and two digits); -1 for a later frame or a bare CR.</summary>
    public int Unit => MessagePrefix.TryReadUnit(Bytes.Span, out int unit) ? unit : -1;

    /// <summary>The header of a first frame (<c>TS</c>, <c>RD</c>, <c>FA</c>); null for a later frame or a bare CR.</summary>
    public string? Header => CaptureText.HeaderOf(Bytes.Span);

    /// <summary>The frame as text, CR as <c>\r</c>.</summary>
    public string Text => FrameText.Printable(Bytes.Span);

    /// <inheritdoc/>
    public override string ToString() => $"{Time:HH:mm:ss.ffffff} {(FromHost ? ">>" : "<<")} {Text}";
}
