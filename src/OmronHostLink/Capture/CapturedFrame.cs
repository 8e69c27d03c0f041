using OmronHostLink.Protocol;

namespace OmronHostLink.Capture;

/// <summary>One record of a capture: a frame (or bytes that did not frame) with when and which way it crossed the line.</summary>
internal sealed class CapturedFrame
{
    public CapturedFrame(DateTimeOffset time, LineDirection direction, byte[] bytes, CaptureFlags flags = CaptureFlags.None, TimeSpan duration = default)
    {
        Time = time;
        Direction = direction;
        Bytes = bytes;
        Flags = flags;
        Duration = duration;
    }

    /// <summary>When the record's last byte crossed the line.</summary>
    public DateTimeOffset Time { get; }

    /// <summary>When its first byte did: <see cref="Time"/> less <see cref="Duration"/>.</summary>
    public DateTimeOffset FirstByteTime => Time - Duration;

    /// <summary>Which way it went.</summary>
    public LineDirection Direction { get; }

    /// <summary>The bytes, CR included.</summary>
    public byte[] Bytes { get; }

    /// <summary>What the recorder knew about them.</summary>
    public CaptureFlags Flags { get; }

    /// <summary>From the first byte to the last; zero when the recorder did not know.</summary>
    public TimeSpan Duration { get; }

    /// <summary>The unit number of a first frame (<c>@</c> and two digits), or -1.</summary>
    public int Unit => MessagePrefix.TryReadUnit(Bytes, out int unit) ? unit : -1;

    /// <summary>The header of a first frame (<c>RD</c>, <c>FA</c>, <c>**</c>), or null.</summary>
    public string? Header => CaptureText.HeaderOf(Bytes);

    /// <inheritdoc/>
    public override string ToString() => $"{Time:HH:mm:ss.ffffff} {(Direction == LineDirection.FromPlc ? "<<" : Direction == LineDirection.ToPlc ? ">>" : "??")} {FrameText.Printable(Bytes)}";
}
