using OmronHostLink.Link;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Tests;

/// <summary>The simulator's serial host by port name, over real socat ptys: restarted on the same pty, and outliving its line.</summary>
[Trait("Category", "Slow")]
public sealed class SerialHostingTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(10);

    private static HostLinkClientOptions Options => new()
    {
        LineTiming = new LineTiming(115200, 11),
        TurnaroundAllowance = Allowances.LosslessLine,
    };

    private static VirtualPlc Plc(ushort value)
    {
        var plc = new VirtualPlc();
        plc.WriteWord(PlcArea.Dm, 0, value);
        return plc;
    }

    [Fact]
    public async Task A_host_stopped_and_started_again_on_the_same_pty_with_default_settings_serves_every_time()
    {
        await using var pair = await SocatPtyPair.StartAsync();
        for (int i = 0; i < 3; i++)
        {
            await using (var host = new SerialSimulatorHost(Plc((ushort)(0x100 + i)), new SerialLineSettings { PortName = pair.PathB }))
            {
                await host.StartAsync();
                await using HostLinkClient client = HostLinkClient.ForSerialPort(pair.PathA, Options);
                (await client.ReadWordsAsync("D0", 1)).Should().Equal((ushort)(0x100 + i));
            }
        }
    }

    [Fact]
    public async Task When_the_line_goes_and_comes_back_the_host_opens_it_again_and_says_so()
    {
        SocatPtyPair pair = await SocatPtyPair.StartAsync();
        SocatPtyPair? again = null;
        var reports = new List<string>();
        try
        {
            await using var host = new SerialSimulatorHost(Plc(0x4242), new SerialLineSettings { PortName = pair.PathB }, r => { lock (reports) { reports.Add(r); } })
            {
                ReopenInterval = TimeSpan.FromMilliseconds(50),
            };
            await host.StartAsync();
            await using (HostLinkClient client = HostLinkClient.ForSerialPort(pair.PathA, Options))
            {
                (await client.ReadWordsAsync("D0", 1)).Should().Equal((ushort)0x4242);
            }

            await pair.CloseAsync();
            await Eventually.UntilAsync(() => { lock (reports) { return reports.Count > 0; } }, "the host reports the lost line");
            host.Completion.IsCompleted.Should().BeFalse("the host waits for the line to come back");
            again = await pair.RestartAsync();

            await using (HostLinkClient client = HostLinkClient.ForSerialPort(again.PathA, Options))
            {
                (await client.ReadWordsAsync("D0", 1).WaitAsync(Patience)).Should().Equal((ushort)0x4242);
            }

            host.Reopened.Should().Be(1);
            lock (reports)
            {
                reports.Should().Equal($"Lost {pair.PathB} 9600 7E2; opening it again when it is back.", $"Serving {pair.PathB} 9600 7E2 again.");
            }

            await host.StopAsync().WaitAsync(Patience);
            host.Completion.IsCompleted.Should().BeTrue();
        }
        finally
        {
            await pair.DisposeAsync();
            if (again is not null)
            {
                await again.DisposeAsync();
            }
        }
    }

    [Fact]
    public async Task Starting_on_a_missing_port_fails_naming_it()
    {
        string path = Path.Combine(Path.GetTempPath(), "no-such-tty-" + Guid.NewGuid().ToString("N"));
        await using var host = new SerialSimulatorHost(new VirtualPlc(), new SerialLineSettings { PortName = path });

        var e = await FluentActions.Awaiting(() => host.StartAsync()).Should().ThrowAsync<HostLinkConnectionException>();
        e.Which.Message.Should().StartWith($"Cannot open serial port {path}: it does not exist.");
    }
}
