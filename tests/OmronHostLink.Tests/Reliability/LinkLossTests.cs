using System.Net;
using System.Net.Sockets;
using System.Text;
using OmronHostLink.Protocol;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Reliability;

/// <summary>
/// The link goes away in the middle of an answer. Decision: both cases surface as
/// <see cref="HostLinkConnectionException"/>, because in both the operating system tells us (TCP: end of stream from
/// the gateway; pty: hang-up when its other side vanishes). Only a line that goes silent without the OS noticing (a
/// cable pulled between a serial-device server and the PLC) is a <see cref="HostLinkTimeoutException"/>; the soak
/// covers that. The next call reconnects: TCP opens a new connection, serial reopens the port path.
/// </summary>
[Collection(SoakCollection.Name)]
public sealed class LinkLossTests
{
    private static HostLinkClientOptions Options => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = Allowances.LosslessLine,
    };

    [Fact]
    public async Task Tcp_gateway_closing_mid_response_is_a_connection_error_and_the_next_call_reconnects()
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 0, 0x1234);
        int accepted = 0;
        Task server = Task.Run(async () =>
        {
            // First connection: read the command, send half an answer, close.
            using (TcpClient first = await listener.AcceptTcpClientAsync())
            {
                accepted++;
                NetworkStream s = first.GetStream();
                await ReadLineAsync(s);
                await s.WriteAsync(Encoding.ASCII.GetBytes("@00RD0012"));
                await s.FlushAsync();
            }

            // Second connection: a proper PLC.
            TcpClient second = await listener.AcceptTcpClientAsync();
            accepted++;
            await plc.RunAsync(second.GetStream());
            second.Dispose();
        });

        await using (HostLinkClient client = HostLinkClient.ForTcp("127.0.0.1", port, Options))
        {
            var e = await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkConnectionException>();
            e.Which.Message.Should().Contain("127.0.0.1");

            (await client.ReadWordsAsync("D0", 1)).Should().Equal(new ushort[] { 0x1234 });
            accepted.Should().Be(2, "the next call opened a new connection");
        }

        listener.Stop();
        await server.WaitAsync(TimeSpan.FromSeconds(5));
    }

    [Fact]
    [Trait("Category", "Slow")]
    public async Task Serial_pty_vanishing_mid_exchange_is_a_connection_error_and_the_port_reopens_when_it_is_back()
    {
        SocatPtyPair pty = await SocatPtyPair.StartAsync();
        SocatPtyPair? again = null;
        await using HostLinkClient client = HostLinkClient.ForSerialPort(new SerialLineSettings { PortName = pty.PathA, BaudRate = 115200 }, Options);
        try
        {
            // The PLC end: read the command, send half an answer, then the line vanishes while the client reads.
            using Stream plcEnd = await SocatPtyPair.OpenAsync(pty.PathB);
            Task<ushort[]> call = client.ReadWordsAsync("D0", 1);
            await ReadLineAsync(plcEnd).WaitAsync(TimeSpan.FromSeconds(5));
            await plcEnd.WriteAsync(Encoding.ASCII.GetBytes("@00RD0012"));
            await plcEnd.FlushAsync();
            await pty.CloseAsync();

            var e = await FluentActions.Awaiting(() => call).Should().ThrowAsync<HostLinkConnectionException>();
            e.Which.Message.Should().Contain(pty.PathA).And.Contain("hung up");

            // Gone: the next call says so, typed.
            await FluentActions.Awaiting(() => client.ReadWordsAsync("D0", 1)).Should().ThrowAsync<HostLinkConnectionException>();

            // Back on the same names, with a PLC behind it: the same client reopens the port.
            again = await pty.RestartAsync();
            var plc = new VirtualPlc();
            plc.WriteWord(PlcArea.Dm, 0, 0x4321);
            await using var host = new SerialSimulatorHost(plc, new SerialLineSettings { PortName = again.PathB });
            await host.StartAsync();
            (await client.ReadWordsAsync("D0", 1)).Should().Equal(new ushort[] { 0x4321 });
        }
        finally
        {
            await pty.DisposeAsync();
            if (again is not null)
            {
                await again.DisposeAsync();
            }
        }
    }

    private static async Task ReadLineAsync(Stream s)
    {
        var one = new byte[1];
        while (await s.ReadAsync(one) == 1 && one[0] != (byte)'\r')
        {
        }
    }
}
