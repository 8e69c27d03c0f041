using System.Text;
using OmronHostLink.Protocol;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// Where the line trace takes a link's frames from, and the only place that knows how: the client's
/// <see cref="HostLinkClient.FrameObserver"/>, stamped with the time and with the unit and command of the exchange a
/// later frame belongs to. Attached only while someone watches the trace; detaching restores the observer the client
/// had. The observer runs on the link's own path: it copies the frame and returns.
/// </summary>
internal sealed class ClientFrameTap : IDisposable
{
    private readonly HostLinkClient _client;
    private readonly TimeProvider _time;
    private readonly Action<LinkFrame> _sink;
    private readonly Action<bool, ReadOnlyMemory<byte>>? _previous;
    private readonly Action<bool, ReadOnlyMemory<byte>> _observer;
    private int _unit = -1;
    private string? _header;

    private ClientFrameTap(HostLinkClient client, TimeProvider time, Action<LinkFrame> sink)
    {
        _client = client;
        _time = time;
        _sink = sink;
        _previous = client.FrameObserver;
        _observer = Observe;
        client.FrameObserver = _previous is null ? _observer : _previous + _observer;
    }

    /// <summary>Starts handing <paramref name="client"/>'s frames to <paramref name="sink"/>, from its next exchange on.</summary>
    public static ClientFrameTap Attach(HostLinkClient client, TimeProvider time, Action<LinkFrame> sink)
    {
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(time);
        ArgumentNullException.ThrowIfNull(sink);
        return new ClientFrameTap(client, time, sink);
    }

    /// <summary>Stops: the client's observer is what it was before (from its next exchange on).</summary>
    public void Dispose() => _client.FrameObserver = _previous;

    private void Observe(bool sent, ReadOnlyMemory<byte> bytes)
    {
        DateTimeOffset now = _time.GetUtcNow();
        ReadOnlySpan<byte> frame = bytes.Span;
        // A first frame names its unit and header (@00RD…), which its exchange's later frames share; INITIALIZE (@**)
        // has no unit.
        if (frame.Length >= 3 && frame[0] == (byte)'@' && frame[1] == (byte)'*' && frame[2] == (byte)'*')
        {
            _unit = -1;
            _header = "**";
        }
        else if (frame.Length >= 5 && MessagePrefix.TryReadUnit(frame, out int unit))
        {
            _unit = unit;
            _header = Encoding.ASCII.GetString(frame.Slice(3, 2));
        }

        _sink(new LinkFrame(sent, now, frame.ToArray(), _unit, _header));
    }
}
