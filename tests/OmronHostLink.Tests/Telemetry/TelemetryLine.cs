using OmronHostLink.Simulator;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Telemetry;

/// <summary>
/// An in-process line for telemetry tests: fast line timing, no retries unless asked, and a way to have exactly the
/// next answer arrive damaged (a retry that then succeeds).
/// </summary>
internal sealed class TelemetryLine : IAsyncDisposable
{
    private readonly InProcessLine _line;
    private int _corruptNext;

    private TelemetryLine(InProcessLine line)
    {
        _line = line;
        line.OnReceive = () =>
        {
            // The damaged answer has arrived: everything after it (the resynchronisation fence, the retry) is clean.
            if (Interlocked.Exchange(ref _corruptNext, 0) == 1)
            {
                Plc.Options.Faults.Corrupt = 0;
            }
        };
    }

    public VirtualPlc Plc => _line.Plc;

    public HostLinkClient Client => _line.Client;

    /// <summary>
    /// Options for these tests: 115200 bps timing, no retries, and the in-process line's allowance (a deadline that only
    /// catches a lost answer; tests of timeouts set their own).
    /// </summary>
    public static HostLinkClientOptions Options(string linkName) => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = InProcessLine.InMemoryAllowance,
        ReadRetries = 0,
        LinkName = linkName,
    };

    public static TelemetryLine Start(HostLinkClientOptions options, VirtualPlcOptions? plc = null)
        => new(InProcessLine.Start(options, plc ?? new VirtualPlcOptions()));

    /// <summary>Makes the simulator damage its next answer frame (one character changed, so its FCS fails).</summary>
    public void CorruptNextAnswer()
    {
        Volatile.Write(ref _corruptNext, 1);
        Plc.Options.Faults.Corrupt = 1;
    }

    public ValueTask DisposeAsync() => _line.DisposeAsync();
}
