using OmronHostLink.Capture;
using OmronHostLink.Protocol;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>One frame (or run of bytes that does not frame) heard on a tapped port, with when its first and last bytes arrived.</summary>
internal sealed class MonitoredFrame
{
    public MonitoredFrame(int source, byte[] bytes, long firstTicks, long lastTicks, bool framed, long earliestTicks = 0)
    {
        Source = source;
        Bytes = bytes;
        EarliestTicks = earliestTicks;
        FirstTicks = firstTicks;
        LastTicks = lastTicks;
        IsFrame = framed;
        Check = FrameCheck.Of(bytes);
    }

    /// <summary>The port it was heard on (0: the one port, or the host's side; 1: the PLC's side).</summary>
    public int Source { get; }

    /// <summary>The bytes, CR included for a frame.</summary>
    public byte[] Bytes { get; }

    /// <summary>
    /// Stopwatch time before which its first byte had provably not arrived: the reader's watermark (<see cref="TapChunk.Clear"/>)
    /// before the read that brought it. With <see cref="FirstTicks"/> it brackets the first byte's arrival, however late the
    /// reader ran.
    /// </summary>
    public long EarliestTicks { get; }

    /// <summary>Stopwatch time of the read that brought its first byte.</summary>
    public long FirstTicks { get; }

    /// <summary>Stopwatch time of the read that brought its last byte.</summary>
    public long LastTicks { get; }

    /// <summary>False for bytes that do not form a frame: before <c>@</c>, or a run cut off by overflow or the end.</summary>
    public bool IsFrame { get; }

    /// <summary>Which way it went: known from the port with two ports, told by the exchange with one.</summary>
    public LineDirection Direction { get; set; }

    /// <summary>What its characters say: ending, FCS, unit.</summary>
    public FrameCheck Check { get; }

    /// <summary>Whether it is a first frame (starts with <c>@</c>).</summary>
    public bool IsFirst => Bytes.Length > 0 && Bytes[0] == (byte)'@';

    /// <summary>Whether it is the bare CR that asks for the next frame of a divided command or answer.</summary>
    public bool IsDelimiter => Bytes.Length == 1 && Bytes[0] == (byte)'\r';

    /// <summary>Whether it is <c>@**</c>, INITIALIZE.</summary>
    public bool IsInitialize => Bytes.Length >= 3 && Bytes[0] == (byte)'@' && Bytes[1] == (byte)'*' && Bytes[2] == (byte)'*';

    /// <summary>The unit of a first frame, or -1.</summary>
    public int Unit => Check.Unit;

    /// <summary>The header of a first frame, or null.</summary>
    public string? Header => CaptureText.HeaderOf(Bytes);

    /// <summary>Whether the frame ends <c>*</c>CR.</summary>
    public bool IsFinal => Check.IsFinal;

    /// <summary>What is wrong with it as a frame (shape, FCS), or null when it is sound. A bare CR and <c>@**</c> are sound.</summary>
    public string? Fault
    {
        get
        {
            if (!IsFrame)
            {
                return "bytes that do not frame";
            }

            if (IsDelimiter || IsInitialize)
            {
                return null;
            }

            return Check.ShapeFault(Bytes) ?? (IsFirst ? Check.FirstFrameFault(Bytes) : null) ?? Check.FcsFault(Bytes);
        }
    }

    /// <summary>The frame as text, CR as <c>\r</c>.</summary>
    public string Text => FrameText.Printable(Bytes);
}
