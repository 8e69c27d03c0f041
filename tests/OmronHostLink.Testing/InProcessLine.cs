using OmronHostLink.Link;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Simulator;
using OmronHostLink.Transports;

namespace OmronHostLink.Testing;

/// <summary>
/// A simulated PLC and a client joined by an in-memory line. Counts the command frames the client sends, so a test
/// can show that nothing was sent or how many transactions a call took.
/// </summary>
public sealed class InProcessLine : IAsyncDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _session;
    private int _sent;

    private InProcessLine(VirtualPlc plc, HostLinkClientOptions options)
    {
        Plc = plc;
        (Stream host, Stream plcEnd) = InMemoryLink.CreatePair();
        _session = plc.RunAsync(plcEnd, _stop.Token);
        options.LineTiming ??= new LineTiming(115200, 11);
        if (options.TurnaroundAllowance == DefaultAllowance)
        {
            options.TurnaroundAllowance = InMemoryAllowance;
        }

        Client = HostLinkClient.ForStream(host, options);
        Client.FrameObserver = (sent, _) =>
        {
            if (sent)
            {
                Interlocked.Increment(ref _sent);
                OnSend?.Invoke();
            }
            else
            {
                OnReceive?.Invoke();
            }
        };
    }

    /// <summary>
    /// The turnaround allowance given to a client that keeps the default. The simulator here answers at once and the
    /// line loses nothing, so the deadline only has to catch a lost answer; what it must not catch is the process being
    /// paused, and the test host holds two thread-pool workers for its own use (the test platform's socket loop and the
    /// adapter's wait for the run), so the first exchanges of a run can wait ~0.5 s for the pool to add a worker.
    /// Tests about deadlines set their own allowance or drive a fake clock.
    /// </summary>
    public static readonly TimeSpan InMemoryAllowance = TimeSpan.FromSeconds(5);

    private static readonly TimeSpan DefaultAllowance = new HostLinkClientOptions().TurnaroundAllowance;

    public VirtualPlc Plc { get; }

    public HostLinkClient Client { get; }

    /// <summary>Called on the client's side as each frame is sent (for example to move a fake clock mid-exchange).</summary>
    public Action? OnSend { get; set; }

    /// <summary>Called on the client's side as each answer frame arrives.</summary>
    public Action? OnReceive { get; set; }

    /// <summary>Frames the client has sent.</summary>
    public int FramesSent => Volatile.Read(ref _sent);

    public static InProcessLine Start(HostLinkClientOptions? options = null, VirtualPlcOptions? plcOptions = null)
        => new(new VirtualPlc(plcOptions), options ?? new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11) });

    public async ValueTask DisposeAsync()
    {
        await Client.DisposeAsync();
        _stop.Cancel();
        await _session;
        _stop.Dispose();
    }
}
