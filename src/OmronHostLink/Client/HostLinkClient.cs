using OmronHostLink.Link;
using OmronHostLink.Transports;

namespace OmronHostLink;

/// <summary>
/// A Host Link client: one link to a serial line (directly, through a TCP serial-device server, or over any stream)
/// and the PLC at <see cref="HostLinkClientOptions.UnitNumber"/> on it. Other units on a multidrop line are reached
/// with <see cref="HostLinkUnit.Unit(int)"/>. Safe for concurrent callers: their exchanges queue and never interleave.
/// </summary>
/// <example>
/// <code>
/// await using var plc = HostLinkClient.ForSerialPort("/dev/ttyUSB0");
/// ushort[] dm = await plc.ReadWordsAsync("D100", 10);
/// await plc.WriteWordAsync("D200", 1234);
/// PlcStatus status = await plc.ReadStatusAsync();
/// </code>
/// </example>
public sealed class HostLinkClient : HostLinkUnit, IHostLinkClient
{
    private HostLinkClient(HostLinkConnection connection, HostLinkClientOptions options)
        : base(connection, options, options.UnitNumber, new UnitModels(options.Model, options.LoggerFactory))
    {
    }

    /// <summary>Creates a client over a transport.</summary>
    /// <exception cref="ArgumentException">An option is not valid.</exception>
    public static HostLinkClient Create(IHostLinkTransport transport, HostLinkClientOptions? options = null)
    {
        Guard.NotNull(transport);
        HostLinkClientOptions o = (options ?? new HostLinkClientOptions()).Clone();
        o.Validate();
        return new HostLinkClient(new HostLinkConnection(transport, o.ToConnectionOptions()), o);
    }

    /// <summary>Creates a client over a stream that is already open (an in-memory pipe, a custom port).</summary>
    /// <param name="stream">A readable and writable stream.</param>
    /// <param name="options">Options; the line timing in them sets the deadlines.</param>
    /// <param name="leaveOpen">True to leave the stream open when the client is disposed.</param>
    public static HostLinkClient ForStream(Stream stream, HostLinkClientOptions? options = null, bool leaveOpen = false)
        => Create(new StreamTransport(stream, leaveOpen), options);

    /// <summary>Creates a client on a serial port with Omron's defaults (9600 bps, 7 data bits, even parity, 2 stop bits).</summary>
    /// <param name="portName">COM3, /dev/ttyUSB0, or any device path.</param>
    /// <param name="options">Client options.</param>
    public static HostLinkClient ForSerialPort(string portName, HostLinkClientOptions? options = null)
        => ForSerialPort(new SerialLineSettings { PortName = portName }, options);

    /// <summary>Creates a client on a serial port with the given line settings. The port opens on the first exchange.</summary>
    public static HostLinkClient ForSerialPort(SerialLineSettings settings, HostLinkClientOptions? options = null)
        => Create(new SerialTransport(settings), options);

    /// <summary>Creates a client for a serial-device server (or the simulator) at <paramref name="host"/>:<paramref name="port"/>.</summary>
    /// <param name="host">Host name or address.</param>
    /// <param name="port">TCP port.</param>
    /// <param name="options">Options; set <see cref="HostLinkClientOptions.LineTiming"/> to the serial side's speed.</param>
    /// <param name="connectTimeout">How long a connection attempt may take (default 5 s).</param>
    public static HostLinkClient ForTcp(string host, int port, HostLinkClientOptions? options = null, TimeSpan? connectTimeout = null)
        => Create(new TcpTransport(host, port, connectTimeout), options);

    /// <summary>Where the link goes (port and settings, host:port).</summary>
    public string Description => Connection.Description;

    /// <summary>
    /// The link's name in metrics and traces: <see cref="HostLinkClientOptions.LinkName"/>, else the port name or
    /// <c>host:port</c>.
    /// </summary>
    public string LinkName => Connection.LinkName;

    /// <summary>Called with every frame sent (true) and received (false), for diagnostics.</summary>
    public Action<bool, ReadOnlyMemory<byte>>? FrameObserver
    {
        get => Connection.FrameObserver;
        set => Connection.FrameObserver = value;
    }

    /// <summary>
    /// Closes the link: waits for the exchange in progress, stops reading and closes the transport. The client is
    /// <see cref="IAsyncDisposable"/> only (use <c>await using</c>): closing waits for I/O, and a blocking
    /// <c>Dispose</c> would have to wait on it synchronously.
    /// </summary>
    public ValueTask DisposeAsync() => Connection.DisposeAsync();
}
