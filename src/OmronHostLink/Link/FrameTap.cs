using OmronHostLink.Capture;

namespace OmronHostLink.Link;

/// <summary>
/// The link's one frame tap: told of every frame the link sends and every frame it takes, with the time, the
/// direction, the unit and the command. The client's trace file, the public <see cref="HostLinkClient.FrameObserver"/>
/// and a host's live line view all hang here. With no tap the link pays one null check a frame; a tap runs on the
/// link's own path, so it must be quick and must not throw.
/// </summary>
internal abstract class FrameTap
{
    /// <summary>Takes one frame; its bytes are valid only during the call.</summary>
    public abstract void OnFrame(in TappedFrame frame);

    /// <summary>A tap that tells both (either may be null).</summary>
    public static FrameTap? Combine(FrameTap? first, FrameTap? second)
        => first is null ? second : second is null ? first : new Pair(first, second);

    private sealed class Pair(FrameTap first, FrameTap second) : FrameTap
    {
        public override void OnFrame(in TappedFrame frame)
        {
            first.OnFrame(frame);
            second.OnFrame(frame);
        }
    }
}

/// <summary>One frame as the link sent or took it.</summary>
internal readonly ref struct TappedFrame
{
    private readonly int _exchangeUnit;
    private readonly string? _exchangeHeader;

    public TappedFrame(LineDirection direction, DateTimeOffset time, ReadOnlySpan<byte> bytes, int exchangeUnit, string? exchangeHeader)
    {
        Direction = direction;
        Time = time;
        Bytes = bytes;
        _exchangeUnit = exchangeUnit;
        _exchangeHeader = exchangeHeader;
    }

    /// <summary><see cref="LineDirection.ToPlc"/> for a frame sent, <see cref="LineDirection.FromPlc"/> for one received.</summary>
    public LineDirection Direction { get; }

    /// <summary>When the link sent it (before the write) or took it (its CR had arrived).</summary>
    public DateTimeOffset Time { get; }

    /// <summary>The frame, CR included.</summary>
    public ReadOnlySpan<byte> Bytes { get; }

    /// <summary>The unit: a first frame's own, else (a later frame, a bare CR) the exchange's; -1 when neither is known.</summary>
    public int Unit => Protocol.MessagePrefix.TryReadUnit(Bytes, out int unit) ? unit : _exchangeUnit;

    /// <summary>The command's header (<c>RD</c>, <c>FA</c>): a first frame's own, else the exchange's.</summary>
    public string? Header => CaptureText.HeaderOf(Bytes) ?? _exchangeHeader;
}
