using System.Net;
using System.Net.Sockets;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;

namespace OmronHostLink.Tests.Client;

/// <summary>
/// <see cref="HostLinkClient.Dispose"/>: what a VB <c>Using</c> block, a C# 7.3 <c>using</c> statement or a form's
/// Dispose calls. It closes the port or socket at once, waiting for nothing; an exchange in progress fails with
/// <see cref="HostLinkConnectionException"/> (inner <see cref="ObjectDisposedException"/>); later calls throw
/// <see cref="ObjectDisposedException"/>.
/// </summary>
public sealed class DisposeTests
{
    /// <summary>Far longer than any test waits: an exchange that ends does so because of Dispose, not its deadline.</summary>
    private static readonly HostLinkClientOptions Patient = new() { TurnaroundAllowance = TimeSpan.FromSeconds(50), ReadRetries = 0 };

    private static readonly TimeSpan Prompt = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task Dispose_during_an_exchange_fails_it_with_a_connection_exception_and_closes_the_socket()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        var client = HostLinkClient.ForTcp("127.0.0.1", ((IPEndPoint)listener.LocalEndpoint).Port, Patient);
        Task<ushort[]> read = client.ReadWordsAsync("D100", 2);
        using Socket plc = await listener.AcceptSocketAsync().WaitAsync(Prompt);
        await ReceiveCommandAsync(plc);
        read.IsCompleted.Should().BeFalse("the silent PLC has not answered");

        client.Dispose();

        (await FluentActions.Awaiting(() => read.WaitAsync(Prompt)).Should().ThrowAsync<HostLinkConnectionException>())
            .Which.InnerException.Should().BeOfType<ObjectDisposedException>();
        plc.ReceiveTimeout = (int)Prompt.TotalMilliseconds;
        plc.Receive(new byte[16]).Should().Be(0, "the client closed its socket");
        await FluentActions.Awaiting(() => client.ReadWordsAsync("D100", 1)).Should().ThrowAsync<ObjectDisposedException>();
    }

    [Fact]
    public async Task Dispose_returns_without_waiting_for_the_exchange_it_ends()
    {
        var (host, plcEnd) = InMemoryLink.CreatePair();
        var client = HostLinkClient.ForStream(host, Patient);
        Task<PlcStatus> status = client.ReadStatusAsync();
        await ReadFrameAsync(plcEnd);

        // On a thread whose every callback is queued behind this one: Dispose must not need it.
        using var ui = new SingleThreadContext();
        await ui.Run(client.Dispose, Prompt);

        await FluentActions.Awaiting(() => status.WaitAsync(Prompt)).Should().ThrowAsync<HostLinkConnectionException>();
        (await plcEnd.ReadAsync(new byte[16]).AsTask().WaitAsync(Prompt)).Should().Be(0, "the client's end of the line was closed");
    }

    [Fact]
    public async Task A_call_queued_behind_the_exchange_gets_ObjectDisposedException()
    {
        var (host, plcEnd) = InMemoryLink.CreatePair();
        var client = HostLinkClient.ForStream(host, Patient);
        Task<PlcStatus> first = client.ReadStatusAsync();
        Task<ushort[]> queued = client.ReadWordsAsync("D0", 1);
        await ReadFrameAsync(plcEnd);

        client.Dispose();

        await FluentActions.Awaiting(() => first.WaitAsync(Prompt)).Should().ThrowAsync<HostLinkConnectionException>();
        await FluentActions.Awaiting(() => queued.WaitAsync(Prompt)).Should().ThrowAsync<ObjectDisposedException>();
    }

    [Fact]
    public async Task A_blocked_caller_is_released_with_the_typed_exception()
    {
        var (host, plcEnd) = InMemoryLink.CreatePair();
        var client = HostLinkClient.ForStream(host, Patient);
        using var ui = new SingleThreadContext();
        Exception? caught = null;
        Task tick = ui.Run(() =>
        {
            try
            {
                client.ReadWordsAsync("D0", 1).GetAwaiter().GetResult();
            }
            catch (Exception e)
            {
                caught = e;
            }
        });
        await ReadFrameAsync(plcEnd);

        client.Dispose();

        await tick.WaitAsync(Prompt);
        caught.Should().BeOfType<HostLinkConnectionException>();
    }

    [Fact]
    public async Task Dispose_and_DisposeAsync_are_idempotent_in_either_order()
    {
        var (host1, plc1) = InMemoryLink.CreatePair();
        var first = HostLinkClient.ForStream(host1, Patient);
        first.Dispose();
        first.Dispose();
        await first.DisposeAsync();
        await FluentActions.Awaiting(() => first.ReadWordsAsync("D0", 1)).Should().ThrowAsync<ObjectDisposedException>();
        (await plc1.ReadAsync(new byte[1]).AsTask().WaitAsync(Prompt)).Should().Be(0);

        var (host2, plc2) = InMemoryLink.CreatePair();
        using var plc = new VirtualPlcSession(plc2);
        var second = HostLinkClient.ForStream(host2, Patient);
        (await second.ReadWordsAsync("D0", 1)).Should().Equal((ushort)0);
        await second.DisposeAsync();
        second.Dispose();
        await second.DisposeAsync();
        await FluentActions.Awaiting(() => second.ReadStatusAsync()).Should().ThrowAsync<ObjectDisposedException>();
    }

    [Fact]
    public async Task Dispose_between_exchanges_closes_an_open_link()
    {
        var (host, plcEnd) = InMemoryLink.CreatePair();
        using var plc = new VirtualPlcSession(plcEnd);
        var client = HostLinkClient.ForStream(host, Patient);
        await client.WriteWordAsync("D10", 7);
        (await client.ReadWordAsync("D10")).Should().Be(7);

        client.Dispose();

        await plc.Ended.WaitAsync(Prompt);
        await FluentActions.Awaiting(() => client.ReadWordAsync("D10")).Should().ThrowAsync<ObjectDisposedException>();
    }

    [Fact]
    public void The_client_and_its_interface_are_IDisposable()
    {
        typeof(IDisposable).IsAssignableFrom(typeof(HostLinkClient)).Should().BeTrue();
        typeof(IDisposable).IsAssignableFrom(typeof(IHostLinkClient)).Should().BeTrue();
    }

    [Fact]
    public async Task Dispose_during_an_exchange_on_a_serial_port_fails_it_promptly_and_closes_the_port()
    {
        await using SocatPtyPair pty = await SocatPtyPair.StartAsync();
        using Stream plcEnd = await SocatPtyPair.OpenAsync(pty.PathB);
        string device = new FileInfo(pty.PathA).ResolveLinkTarget(returnFinalTarget: true)!.FullName;
        var client = HostLinkClient.ForSerialPort(pty.PathA, Patient);
        Task<ushort[]> read = client.ReadWordsAsync("D100", 2);
        await ReadFrameAsync(plcEnd);
        OpenHandles(device).Should().Be(1, "the client holds the port during the exchange");
        read.IsCompleted.Should().BeFalse("the silent PLC has not answered");

        client.Dispose();

        (await FluentActions.Awaiting(() => read.WaitAsync(Prompt)).Should().ThrowAsync<HostLinkConnectionException>())
            .Which.InnerException.Should().BeOfType<ObjectDisposedException>();
        SpinWait.SpinUntil(() => OpenHandles(device) == 0, Prompt).Should().BeTrue("Dispose closed the port");
    }

    /// <summary>How many of this process's file descriptors are open on <paramref name="device"/> (Linux /proc).</summary>
    private static int OpenHandles(string device)
        => new DirectoryInfo("/proc/self/fd").EnumerateFileSystemInfos()
            .Count(fd =>
            {
                try
                {
                    return fd.LinkTarget == device;
                }
                catch (IOException)
                {
                    return false;
                }
            });

    private static async Task ReceiveCommandAsync(Socket plc)
    {
        var buffer = new byte[64];
        while (true)
        {
            int n = await plc.ReceiveAsync(buffer).WaitAsync(Prompt);
            if (n == 0 || Array.IndexOf(buffer, (byte)'\r', 0, n) >= 0)
            {
                return;
            }
        }
    }

    private static async Task ReadFrameAsync(Stream plcEnd)
    {
        var one = new byte[1];
        while (await plcEnd.ReadAsync(one).AsTask().WaitAsync(Prompt) == 1 && one[0] != '\r')
        {
        }
    }

    /// <summary>A simulated PLC on the PLC's end of an in-memory line, for as long as the line is open.</summary>
    private sealed class VirtualPlcSession : IDisposable
    {
        private readonly CancellationTokenSource _stop = new();

        public VirtualPlcSession(Stream plcEnd)
            => Ended = new OmronHostLink.Simulator.VirtualPlc().RunAsync(plcEnd, _stop.Token);

        /// <summary>Ends when the client closes its end of the line.</summary>
        public Task Ended { get; }

        public void Dispose()
        {
            _stop.Cancel();
            _stop.Dispose();
        }
    }
}
