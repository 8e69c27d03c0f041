using OmronHostLink.Tests.Infrastructure;
using OmronHostLink.Transports;

namespace OmronHostLink.Tests.Transports;

/// <summary>
/// A port that cannot be opened is a <see cref="HostLinkConnectionException"/> that names it once, says what is wrong
/// and what to do. Failures this machine can produce are real; the others (permission, a busy port, Windows) are
/// thrown by a stand-in port in the shape System.IO.Ports gives them, which the real cases check.
/// </summary>
public sealed class SerialOpenFailureTests
{
    private const string Prefix = "Cannot open serial port ";

    private static async Task<HostLinkConnectionException> OpenFailsAsync(SerialTransport transport)
    {
        var e = await FluentActions.Awaiting(() => transport.OpenAsync(CancellationToken.None).AsTask())
            .Should().ThrowAsync<HostLinkConnectionException>();
        CountOf(e.Which.Message, Prefix).Should().Be(1, "the prefix must not be doubled: {0}", e.Which.Message);
        return e.Which;
    }

    private static int CountOf(string text, string part)
    {
        int count = 0;
        for (int i = text.IndexOf(part, StringComparison.Ordinal); i >= 0; i = text.IndexOf(part, i + 1, StringComparison.Ordinal))
        {
            count++;
        }

        return count;
    }

    private static SerialTransport Failing(string port, Exception error)
        => new(new SerialLineSettings { PortName = port }, s => new FakeSerialPort(s.PortName) { OpenFails = error });

    [Fact]
    public async Task A_missing_path_says_it_does_not_exist_and_where_to_look()
    {
        string path = Path.Combine(Path.GetTempPath(), "no-such-tty-" + Guid.NewGuid().ToString("N"));

        HostLinkConnectionException e = await OpenFailsAsync(new SerialTransport(new SerialLineSettings { PortName = path }));

        e.Message.Should().Be($"Cannot open serial port {path}: it does not exist. Check that the device is plugged in and the path is right (ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id/).");
        e.InnerException.Should().BeOfType<UnauthorizedAccessException>("System.IO.Ports reports every failed open on Unix so")
            .Which.InnerException.Should().BeOfType<IOException>();
    }

    [Fact]
    public async Task A_socat_link_whose_pty_is_gone_says_it_does_not_exist()
    {
        string link = Path.Combine(Path.GetTempPath(), "ohl-dangling-" + Guid.NewGuid().ToString("N"));
        File.CreateSymbolicLink(link, "/dev/pts/987654");
        try
        {
            HostLinkConnectionException e = await OpenFailsAsync(new SerialTransport(new SerialLineSettings { PortName = link }));
            e.Message.Should().StartWith($"Cannot open serial port {link}: it does not exist.");
        }
        finally
        {
            File.Delete(link);
        }
    }

    [Fact]
    public async Task A_regular_file_is_not_a_serial_device()
    {
        string path = Path.GetTempFileName();
        try
        {
            HostLinkConnectionException e = await OpenFailsAsync(new SerialTransport(new SerialLineSettings { PortName = path }));

            e.Message.Should().Be($"Cannot open serial port {path}: it is not a serial device. Give the path of a serial port (/dev/ttyUSB0, /dev/ttyS0) or a pseudo-terminal.");
            e.InnerException.Should().BeOfType<UnauthorizedAccessException>()
                .Which.InnerException.Should().BeOfType<IOException>()
                .Which.HResult.Should().Be(25, "the inner exception carries errno (ENOTTY), which the stand-in cases rely on");
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public async Task Asking_for_DTR_on_a_pty_fails_naming_DTR_and_the_port_is_released()
    {
        await using var pair = await SocatPtyPair.StartAsync();

        HostLinkConnectionException e = await OpenFailsAsync(new SerialTransport(new SerialLineSettings { PortName = pair.PathA, DtrEnable = true }));

        e.Message.Should().StartWith($"Cannot open serial port {pair.PathA}: cannot raise DTR (")
            .And.EndWith("). Turn DtrEnable off: pseudo-terminals and some adapters have no modem-control lines.");
        using Stream again = await SocatPtyPair.OpenAsync(pair.PathA);
        again.CanRead.Should().BeTrue();
    }

    [Fact]
    public async Task Permission_denied_says_to_join_the_dialout_group()
    {
        HostLinkConnectionException e = await OpenFailsAsync(Failing("/dev/null", new UnauthorizedAccessException(
            "Access to the port '/dev/null' is denied.", new IOException("Permission denied", 13))));

        e.Message.Should().Be("Cannot open serial port /dev/null: permission denied. Add the user to the group that owns the device (usually dialout: sudo usermod -aG dialout $USER, then log in again).");
    }

    [Fact]
    public async Task A_busy_port_says_to_close_the_other_program()
    {
        HostLinkConnectionException e = await OpenFailsAsync(Failing("/dev/null", new UnauthorizedAccessException(
            "Access to the port '/dev/null' is denied.", new IOException("Device or resource busy", 16))));

        e.Message.Should().Be("Cannot open serial port /dev/null: it is in use by another program. Close the other program (a terminal, another hostlink, the worker service) and try again.");
    }

    [Fact]
    public async Task Refused_line_settings_are_named()
    {
        var settings = new SerialLineSettings { PortName = "/dev/null", BaudRate = 19200, Parity = SerialParity.Odd };
        var transport = new SerialTransport(settings, s => new FakeSerialPort(s.PortName) { OpenFails = new ArgumentException("Value does not fall within the expected range.") });

        HostLinkConnectionException e = await OpenFailsAsync(transport);

        e.Message.Should().Be("Cannot open serial port /dev/null: the device refused the line settings 19200 7O2. Check that the adapter supports them (some USB adapters lack 7 data bits or 2 stop bits).");
    }

    [Fact]
    public async Task Another_error_keeps_the_operating_systems_words_without_the_port_name_twice()
    {
        HostLinkConnectionException e = await OpenFailsAsync(Failing("/dev/null", new UnauthorizedAccessException(
            "Access to the port '/dev/null' is denied.", new IOException("Too many open files", 24))));

        e.Message.Should().Be("Cannot open serial port /dev/null: Too many open files.");
    }

    [Fact]
    public async Task A_port_that_fails_after_opening_is_closed_again()
    {
        var port = new FakeSerialPort("/dev/null", new MemoryStream()) { DtrFails = new IOException("Inappropriate ioctl for device", 25) };
        var transport = new SerialTransport(new SerialLineSettings { PortName = "/dev/null", DtrEnable = true }, _ => port);

        await OpenFailsAsync(transport);

        port.Disposed.Should().BeTrue();
    }

    [Fact]
    public async Task DTR_and_RTS_are_raised_only_when_asked_for()
    {
        var quiet = new FakeSerialPort("/dev/null", new MemoryStream());
        await using (var transport = new SerialTransport(new SerialLineSettings { PortName = "/dev/null" }, _ => quiet))
        {
            await transport.OpenAsync(CancellationToken.None);
        }

        (quiet.Dtr, quiet.Rts).Should().Be((false, false));

        var raised = new FakeSerialPort("/dev/null", new MemoryStream());
        await using (var transport = new SerialTransport(new SerialLineSettings { PortName = "/dev/null", DtrEnable = true, RtsEnable = true }, _ => raised))
        {
            await transport.OpenAsync(CancellationToken.None);
        }

        (raised.Dtr, raised.Rts).Should().Be((true, true));
        raised.Disposed.Should().BeTrue("disposing the transport closed the port");
    }

    public static TheoryData<string, Exception, string> WindowsCases => new()
    {
        {
            "COM3",
            new UnauthorizedAccessException("Access to the port 'COM3' is denied."),
            "Cannot open serial port COM3: access is denied: it is most likely in use by another program. Close the other program (a terminal, another hostlink, the worker service) and try again."
        },
        {
            "COM9",
            new IOException("The port 'COM9' does not exist."),
            "Cannot open serial port COM9: it does not exist. Check that the adapter is plugged in and the port's COM number in Device Manager (Ports (COM & LPT))."
        },
        {
            "COM3",
            new IOException("The parameter is incorrect.", unchecked((int)0x80070057)),
            "Cannot open serial port COM3: the device refused the line settings 9600 7E2. Check that the adapter supports them (some USB adapters lack 7 data bits or 2 stop bits)."
        },
        {
            "LPT1",
            new ArgumentException("The given port name (LPT1) does not resolve to a valid serial port."),
            "Cannot open serial port LPT1: this is not a serial port name. Use the port's COM name, such as COM3."
        },
    };

    [Theory]
    [MemberData(nameof(WindowsCases))]
    public void Windows_failures_are_named_and_say_what_to_do(string port, Exception error, string expected)
    {
        HostLinkConnectionException e = SerialOpenFailure.Describe(new SerialLineSettings { PortName = port }, error, SerialOpenFailure.Stage.Open, windows: true, exists: _ => true);

        e.Message.Should().Be(expected);
        e.InnerException.Should().BeSameAs(error);
    }
}
