using OmronHostLink.Capture;

namespace OmronHostLink.Link;

/// <summary>The public <see cref="HostLinkClient.FrameObserver"/> on the link's tap: sent frames as they are, received ones copied.</summary>
internal sealed class ObserverTap(Action<bool, ReadOnlyMemory<byte>> observer) : FrameTap
{
    public Action<bool, ReadOnlyMemory<byte>> Observer { get; } = observer;

    public override void OnFrame(in TappedFrame frame)
        => Observer(frame.Direction == LineDirection.ToPlc, frame.Bytes.ToArray());
}
