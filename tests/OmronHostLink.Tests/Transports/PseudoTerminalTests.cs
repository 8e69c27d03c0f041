using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>Recognising a pseudo-terminal by the device its name leads to, without termios or ioctl.</summary>
public sealed class PseudoTerminalTests
{
    [Theory]
    [InlineData("/dev/pts/0", true)]
    [InlineData("/dev/pts/17", true)]
    [InlineData("/dev/ttys003", true)]
    [InlineData("/dev/pts/", false)]
    [InlineData("/dev/pts/ptmx", false)]
    [InlineData("/dev/ttyS0", false)]
    [InlineData("/dev/ttyUSB0", false)]
    [InlineData("/dev/ttyACM1", false)]
    [InlineData("/dev/tty.usbserial-A1", false)]
    [InlineData("COM3", false)]
    public void Device_paths(string path, bool pty) => PseudoTerminal.IsDevicePath(path).Should().Be(pty);

    [Fact]
    public async Task A_socat_link_leads_to_a_pty()
    {
        await using var pair = await SocatPtyPair.StartAsync();

        PseudoTerminal.DevicePath(pair.PathA).Should().StartWith("/dev/pts/");
        PseudoTerminal.Is(pair.PathA).Should().BeTrue();
        PseudoTerminal.Is(PseudoTerminal.DevicePath(pair.PathB)).Should().BeTrue();
    }

    [Fact]
    public void Other_files_and_missing_paths_are_not_ptys()
    {
        PseudoTerminal.Is("/dev/null").Should().BeFalse();
        PseudoTerminal.Is("/tmp/no-such-device-" + Guid.NewGuid().ToString("N")).Should().BeFalse();
    }
}
