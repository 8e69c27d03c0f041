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
    /// The turnaround allowance given to a client that keeps the default: <see cref="Allowances.LosslessLine"/>, since
    /// the simulator here answers at once and the line loses nothing. Tests about deadlines set their own allowance or
    /// drive a fake clock.
    /// </summary>
    public static readonly TimeSpan InMemoryAllowance = Allowances.LosslessLine;

    private static readonly TimeSpan DefaultAllowance = new HostLinkClientOptions().TurnaroundAllowance;

    public VirtualPlc Plc { get; }

    public HostLinkClient Client { get; }

    /// <summary>Called on the client's side as each frame is sent (for example to move a fake clock mid-exchange).</summary>
    public Action? OnSend { get; set; }

    /// <summary>Called on the client's side as each answer frame arrives.</summary>
    public Action? OnReceive { get; set; }

    /// <summary>Frames the client has sent.</summary>
    public int FramesSent => Volatile.Read(ref _sent);

    /// <remarks>
    /// Without <paramref name="options"/> the client reads by area only (<see cref="CompoundReadMode.Off"/>), so that
    /// tests which count frames count the reads they are about, not an MM and a QQ registration.
    /// </remarks>
    public static InProcessLine Start(HostLinkClientOptions? options = null, VirtualPlcOptions? plcOptions = null)
        => new(new VirtualPlc(plcOptions), options ?? new HostLinkClientOptions { LineTiming = new LineTiming(115200, 11), UseCompoundRead = CompoundReadMode.Off });

    public async ValueTask DisposeAsync()
    {
        await Client.DisposeAsync();
        _stop.Cancel();
        await _session;
        _stop.Dispose();
    }
}
