using System.Net;
using System.Net.Sockets;
using System.Text;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Simulator.Tests;

/// <summary>TCP and serial hosting of a simulated PLC.</summary>
public class HostingTests
{
    private static async Task<string> TransactAsync(Stream stream, string frame)
    {
        await stream.WriteAsync(Encoding.ASCII.GetBytes(frame));
        await stream.FlushAsync();
        var sb = new StringBuilder();
        var one = new byte[1];
        using var cts = new CancellationTokenSource(RawHost.DefaultTimeout);
        while (!sb.ToString().EndsWith('\r'))
        {
            int n = await stream.ReadAsync(one, cts.Token);
            if (n == 0)
            {
                throw new EndOfStreamException();
            }

            sb.Append((char)one[0]);
        }

        return sb.ToString();
    }

    [Fact]
    public async Task The_TCP_host_listens_on_loopback_with_an_ephemeral_port_and_serves_each_connection()
    {
        var plc = new VirtualPlc();
        await using var host = new TcpSimulatorHost(plc);
        await host.StartAsync();
        host.EndPoint.Address.Should().Be(IPAddress.Loopback);
        host.EndPoint.Port.Should().NotBe(0);

        using (var client = new TcpClient())
        {
            await client.ConnectAsync(host.EndPoint);
            (await TransactAsync(client.GetStream(), RawHost.Command("@00WD00051234"))).Should().Be(RawHost.Command("@00WD00"));
        }

        // A reconnect reaches the same PLC memory.
        using (var client = new TcpClient())
        {
            await client.ConnectAsync(host.EndPoint);
            (await TransactAsync(client.GetStream(), RawHost.Command("@00RD00050001"))).Should().Be(RawHost.Command("@00RD001234"));
            host.AcceptedConnections.Should().Be(2);
        }

        await host.StopAsync();
        host.ActiveSessions.Should().Be(0);
    }

    [Fact]
    public async Task Stopping_the_TCP_host_closes_open_connections()
    {
        await using var host = new TcpSimulatorHost(new VirtualPlc());
        await host.StartAsync();
        using var client = new TcpClient();
        await client.ConnectAsync(host.EndPoint);
        NetworkStream stream = client.GetStream();
        (await TransactAsync(stream, RawHost.Command("@00MS"))).Should().StartWith("@00MS00");
        await host.StopAsync().WaitAsync(RawHost.DefaultTimeout);
        var buffer = new byte[1];
        using var cts = new CancellationTokenSource(RawHost.DefaultTimeout);
        int n;
        try
        {
            n = await stream.ReadAsync(buffer, cts.Token);
        }
        catch (IOException)
        {
            n = 0;
        }

        n.Should().Be(0);
    }

    [Fact]
    public async Task The_serial_host_runs_a_session_on_the_stream_it_opens()
    {
        var (hostEnd, plcEnd) = InMemoryLink.CreatePair();
        await using var host = new SerialSimulatorHost(new VirtualPlc(new VirtualPlcOptions { Units = [5] }), () => plcEnd);
        await host.StartAsync();
        (await TransactAsync(hostEnd, RawHost.Command("@05MM"))).Should().Be(RawHost.Command("@05MM0030"));
        await hostEnd.DisposeAsync();
        await host.Completion.WaitAsync(RawHost.DefaultTimeout);
        await host.StopAsync();
    }
}
