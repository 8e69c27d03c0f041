using System.Text;
using OmronHostLink.Simulator.Hosting;
using OmronHostLink.Transports;

namespace OmronHostLink.Simulator.Tests;

/// <summary>The emulated serial line: a host at the PLC port's settings is answered, at others it hears what a real line gives.</summary>
public sealed class EmulatedSerialLineTests
{
    private static readonly byte[] Ts = Encoding.ASCII.GetBytes(GoldenFrames.Frames("java_ts")[0]);

    [Fact]
    public async Task A_host_at_the_ports_settings_is_answered_and_the_frames_are_logged()
    {
        var log = new SimulatorFrameLog();
        var line = new EmulatedSerialLine(Line(log), UartModelTests.Settings(19200, "8N1"));

        byte[] answer = await ExchangeAsync(line, UartModelTests.Settings(19200, "8N1"), Ts, expected: Ts.Length);

        answer.Should().Equal(Ts, "TS is answered with its own characters");
        log.Frames.Select(f => (f.FromHost, f.Text)).Should().Equal((true, @"@00TS==HelloPLC5A*\r"), (false, @"@00TS==HelloPLC5A*\r"));
        line.HostTransmissions.Should().ContainSingle().Which.Bytes.Should().Equal(Ts);
    }

    [Fact]
    public async Task A_host_at_other_settings_gets_silence_and_the_port_ignores_the_damaged_frame()
    {
        var log = new SimulatorFrameLog();
        var line = new EmulatedSerialLine(Line(log), UartModelTests.Settings(9600, "7E2"));

        byte[] answer = await ExchangeAsync(line, UartModelTests.Settings(9600, "8N1"), Ts, expected: 0);

        answer.Should().BeEmpty();
        line.FramesWithLineErrors.Should().Be(1, "'@' arrives with a parity error, and a CS/CJ port ignores such a frame");
        log.Count.Should().Be(0);
    }

    [Fact]
    public async Task A_two_wire_line_echoes_the_hosts_frame_before_the_answer()
    {
        var line = new EmulatedSerialLine(Line(new SimulatorFrameLog()), UartModelTests.Settings(9600, "7E2"), twoWireEcho: true);

        byte[] heard = await ExchangeAsync(line, UartModelTests.Settings(9600, "7E2"), Ts, expected: 2 * Ts.Length);

        heard.Should().Equal([.. Ts, .. Ts]);
    }

    private static VirtualPlcLine Line(SimulatorFrameLog log) => new([new VirtualPlc(new VirtualPlcOptions { FrameLog = log })]);

    /// <summary>Opens the host's port, sends, and reads until <paramref name="expected"/> bytes came (or, for 0, until the session has seen the frame).</summary>
    private static async Task<byte[]> ExchangeAsync(EmulatedSerialLine line, SerialLineSettings host, byte[] frame, int expected)
    {
        IHostLinkTransport port = line.Transport(host);
        Stream stream = await port.OpenAsync(CancellationToken.None);
        await stream.WriteAsync(frame);
        var heard = new List<byte>();
        var buffer = new byte[256];
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(10));
        while (heard.Count < expected)
        {
            int n = await stream.ReadAsync(buffer, timeout.Token);
            heard.AddRange(buffer.AsSpan(0, n));
        }

        // Closing ends the PLC's session: whatever it would have sent is in by then.
        await port.CloseAsync();
        return heard.ToArray();
    }
}
