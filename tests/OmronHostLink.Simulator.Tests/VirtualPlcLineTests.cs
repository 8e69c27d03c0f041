using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Simulator.Tests;

/// <summary>Several virtual PLCs on one line, each with its own unit numbers and state.</summary>
public sealed class VirtualPlcLineTests
{
    [Fact]
    public async Task Each_plc_answers_its_own_units_from_its_own_memory()
    {
        var line = VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [0, 4] });
        line[0].WriteWord(PlcArea.Dm, 0, 11);
        line[4].WriteWord(PlcArea.Dm, 0, 44);
        line[4].Mode = PlcMode.Run;
        await using var host = new TcpSimulatorHost(line);
        await host.StartAsync();
        await using HostLinkClient client = HostLinkClient.ForTcp("127.0.0.1", host.EndPoint.Port, new HostLinkClientOptions { TurnaroundAllowance = Allowances.LosslessLine });

        ushort zero = await client.ReadWordAsync("D0");
        ushort four = await client.Unit(4).ReadWordAsync("D0");
        PlcStatus status0 = await client.ReadStatusAsync();
        PlcStatus status4 = await client.Unit(4).ReadStatusAsync();

        zero.Should().Be(11);
        four.Should().Be(44);
        status0.Mode.Should().Be(PlcMode.Program);
        status4.Mode.Should().Be(PlcMode.Run);
        line.Units.Should().Equal(0, 4);
    }

    [Fact]
    public void A_unit_answered_by_two_plcs_is_refused()
    {
        var a = new VirtualPlc(new VirtualPlcOptions { Units = [0, 1] });
        var b = new VirtualPlc(new VirtualPlcOptions { Units = [1] });

        FluentActions.Invoking(() => new VirtualPlcLine([a, b])).Should().Throw<ArgumentException>().WithMessage("*Unit 01*");
    }

    [Fact]
    public void Plcs_of_one_line_share_its_speed()
    {
        var a = new VirtualPlc(new VirtualPlcOptions { Units = [0], BaudRate = 9600 });
        var b = new VirtualPlc(new VirtualPlcOptions { Units = [1], BaudRate = 19200 });

        FluentActions.Invoking(() => new VirtualPlcLine([a, b])).Should().Throw<ArgumentException>();
    }
}
