using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>
/// A virtual PLC in process and a client on it, for telemetry tests: fast line timing, no retries unless asked, and a
/// way to have exactly the next answer arrive damaged (a retry that then succeeds).
/// </summary>
internal sealed class TelemetryLine : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _session;
    private int _corruptNext;

    private TelemetryLine(VirtualPlc plc, HostLinkClientOptions options)
    {
        Plc = plc;
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _session = plc.RunAsync(plcEnd, _stop.Token);
        Client = HostLinkClient.ForStream(host, options);
        Client.FrameObserver = (sent, _) =>
        {
            // The damaged answer has arrived: everything after it (the resynchronisation fence, the retry) is clean.
            if (!sent && Interlocked.Exchange(ref _corruptNext, 0) == 1)
            {
                Plc.Options.Faults.Corrupt = 0;
            }
        };
    }

    public VirtualPlc Plc { get; }

    public HostLinkClient Client { get; }

    /// <summary>Options for these tests: 115200 bps timing, a generous turnaround (the machine is shared), no retries.</summary>
    public static HostLinkClientOptions Options(string linkName) => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = TimeSpan.FromMilliseconds(500),
        ReadRetries = 0,
        LinkName = linkName,
    };

    public static TelemetryLine Start(HostLinkClientOptions options, VirtualPlcOptions? plc = null)
        => new(new VirtualPlc(plc ?? new VirtualPlcOptions()), options);

    /// <summary>Makes the simulator damage its next answer frame (one character changed, so its FCS fails).</summary>
    public void CorruptNextAnswer()
    {
        Volatile.Write(ref _corruptNext, 1);
        Plc.Options.Faults.Corrupt = 1;
    }

    public async ValueTask DisposeAsync()
    {
        await Client.DisposeAsync();
        _stop.Cancel();
        await _session;
        _stop.Dispose();
    }
}
