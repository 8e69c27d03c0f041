using System.Text;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Models;

/// <summary>
/// A client (with <c>Model</c> and <c>HostLinkCompatibleMode</c> set as given) on an in-memory line to a simulated PLC,
/// keeping what it writes to the line, so a test can show that nothing was sent, or what was.
/// </summary>
internal sealed class EmulatedLine : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _session;
    private readonly List<string> _sent = [];

    private EmulatedLine(VirtualPlc plc, string? model, HostLinkCompatibleMode? compatibleMode, Action<HostLinkClientOptions>? configure)
    {
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _session = plc.RunAsync(plcEnd, _stop.Token);
        var options = new HostLinkClientOptions
        {
            LineTiming = new LineTiming(115200, 11),
            TurnaroundAllowance = InProcessLine.InMemoryAllowance,
            Model = model,
            HostLinkCompatibleMode = compatibleMode,
        };
        configure?.Invoke(options);
        Client = HostLinkClient.ForStream(host, options);
        Client.FrameObserver = (sent, frame) =>
        {
            if (sent)
            {
                lock (_sent)
                {
                    _sent.Add(Encoding.ASCII.GetString(frame.Span));
                }
            }
        };
    }

    public HostLinkClient Client { get; }

    /// <summary>Bytes the client has written to the line (every write goes through the link's frame observer).</summary>
    public long BytesSent => SentFrames.Sum(f => (long)f.Length);

    /// <summary>The frames the client has sent, as text.</summary>
    public IReadOnlyList<string> SentFrames
    {
        get
        {
            lock (_sent)
            {
                return [.. _sent];
            }
        }
    }

    public static EmulatedLine Start(VirtualPlc plc, string? model, HostLinkCompatibleMode? compatibleMode = null, Action<HostLinkClientOptions>? configure = null)
        => new(plc, model, compatibleMode, configure);

    public async ValueTask DisposeAsync()
    {
        await Client.DisposeAsync();
        _stop.Cancel();
        await _session;
        _stop.Dispose();
    }
}
