using System.Net;
using OmronHostLink.Simulator;
using OmronHostLink.Simulator.Hosting;

namespace OmronHostLink.Com.Tests;

/// <summary>
/// Units 00 and 01 of the simulator, served in this process on 127.0.0.1, with the values the scripts read set here;
/// the tests check what the scripts print and what they wrote against this memory, never against the server itself.
/// </summary>
public sealed class Simulation : IAsyncDisposable
{
    private TcpSimulatorHost _host;

    private Simulation(VirtualPlcLine line, TcpSimulatorHost host)
    {
        Line = line;
        _host = host;
    }

    public VirtualPlcLine Line { get; }

    public VirtualPlc Unit0 => Line[0];

    public VirtualPlc Unit1 => Line[1];

    /// <summary>host:port.</summary>
    public string Endpoint => $"127.0.0.1:{_host.EndPoint.Port}";

    public static async Task<Simulation> StartAsync()
    {
        VirtualPlcLine line = VirtualPlcLine.OnePlcPerUnit(new VirtualPlcOptions { Units = [0, 1] });
        var host = new TcpSimulatorHost(line, new IPEndPoint(IPAddress.Loopback, 0));
        await host.StartAsync();
        var simulation = new Simulation(line, host);
        simulation.Fill();
        return simulation;
    }

    /// <summary>The values the scripts read: D100-D109 = 1000..1009, a bit, a REAL, BCD, LREAL, DINT, text.</summary>
    private void Fill()
    {
        Unit0.WriteWords("D100", Enumerable.Range(1000, 10).Select(v => (ushort)v).ToArray());
        Unit0.WriteWords("D120", [0b1000]);                                          // D120.03 on
        Unit0.WriteWords("D130", Words(BitConverter.SingleToInt32Bits(1.5f)));       // REAL, low word first
        Unit0.WriteWords("D150", [0x1234]);                                          // BCD 1234
        Unit0.WriteWords("D160", LongWords(BitConverter.DoubleToInt64Bits(-2.75)));  // LREAL
        Unit0.WriteWords("D170", Words(-70000));                                     // DINT
        Unit0.WriteWords("D180", [0x4142, 0x4344, 0x4546, 0x4748]);                  // "ABCDEFGH"
        Unit1.WriteWords("D100", [2024]);
    }

    /// <summary>Stops serving: the next exchange of a client finds the port closed.</summary>
    public Task StopAsync() => _host.StopAsync();

    public async ValueTask DisposeAsync() => await _host.DisposeAsync();

    private static ushort[] Words(int value) => [(ushort)(value & 0xFFFF), (ushort)((value >> 16) & 0xFFFF)];

    private static ushort[] LongWords(long value)
        => [(ushort)(value & 0xFFFF), (ushort)((value >> 16) & 0xFFFF), (ushort)((value >> 32) & 0xFFFF), (ushort)((value >> 48) & 0xFFFF)];
}
