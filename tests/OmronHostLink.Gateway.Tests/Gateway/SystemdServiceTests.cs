using System.Globalization;
using System.Net;
using System.Net.Sockets;
using Xunit.Abstractions;

namespace OmronHostLink.Gateway.Tests.Gateway;

/// <summary>
/// The worker as a <c>Type=notify</c> systemd service, without systemd: the test is the service manager. It binds the
/// notification socket, starts the worker process as systemd would (see <see cref="ServiceProcess"/>) with
/// <c>NOTIFY_SOCKET</c> pointing at it, and reads what the worker reports.
/// </summary>
public sealed class SystemdServiceTests(ITestOutputHelper output)
{
    // A cold start of a .NET process on a busy 2-core machine takes seconds; these only bound a hang.
    private static readonly TimeSpan StartPatience = TimeSpan.FromSeconds(60);
    private static readonly TimeSpan StopPatience = TimeSpan.FromSeconds(30);

    [LinuxFact]
    public async Task Started_by_systemd_the_worker_notifies_READY_once_started_and_STOPPING_on_SIGTERM_then_exits_0()
    {
        int port = FreeLoopbackPort();
        string[] args =
        [
            // The worker's own virtual PLC, polled over TCP loopback: nothing outside the process is needed.
            "--Simulator:Enabled=true",
            $"--Simulator:Port={port.ToString(CultureInfo.InvariantCulture)}",
            "--Simulator:Memory:D100=1234",
            $"--HostLink:Links:sim:Tcp=127.0.0.1:{port.ToString(CultureInfo.InvariantCulture)}",
            "--HostLink:Links:sim:Serial:BaudRate=115200",
            $"--HostLink:Links:sim:TurnaroundAllowance={Allowances.LosslessLineText}",
            "--HostLink:Links:sim:Groups:level:Address=D100",
            "--HostLink:Links:sim:Groups:level:Type=int16",
            "--HostLink:Links:sim:Groups:level:Interval=00:00:00.200",
        ];

        using NotifySocket notify = NotifySocket.Bind();
        await using ServiceProcess worker = await ServiceProcess.StartUnderSystemdAsync(args, new Dictionary<string, string> { ["NOTIFY_SOCKET"] = notify.Path });
        try
        {
            string? ready = await notify.ReceiveAsync(StartPatience);
            ready.Should().Be("READY=1", "the worker reports readiness once started; {0}", worker);

            // READY=1 comes after every hosted service has started: the simulator is listening already.
            using (var probe = new TcpClient())
            {
                await probe.ConnectAsync(IPAddress.Loopback, port);
            }

            string? value = await worker.WaitForLineAsync(l => l.Contains("sim/level: unit 0 D100 = 1234", StringComparison.Ordinal), StartPatience);
            value.Should().NotBeNull("the link polls the simulator; {0}", worker);
            value.Should().StartWith("<6>", "under systemd the console log uses the journal's format (syslog priority prefix)");
            notify.Available.Should().Be(0, "nothing but READY=1 is sent while the worker runs");

            worker.Signal(ProgramProcess.SigTerm);

            string? stopping = await notify.ReceiveAsync(StopPatience);
            stopping.Should().Be("STOPPING=1", "SIGTERM starts a graceful stop that is reported to systemd; {0}", worker);
            int? exitCode = await worker.WaitForExitAsync(StopPatience);
            exitCode.Should().Be(0, "a graceful stop exits 0 (systemd would count anything else as a failure); {0}", worker);
            worker.Lines.Should().Contain(l => l.Contains("link sim: stopped after", StringComparison.Ordinal), "the link closes cleanly");
        }
        finally
        {
            output.WriteLine(worker.ToString());
        }
    }

    private static int FreeLoopbackPort()
    {
        using var probe = new TcpListener(IPAddress.Loopback, 0);
        probe.Start();
        int port = ((IPEndPoint)probe.LocalEndpoint).Port;
        probe.Stop();
        return port;
    }
}
