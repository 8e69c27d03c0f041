using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>
/// Turns what System.IO.Ports throws while opening a port into a <see cref="HostLinkConnectionException"/> that names
/// the port, says what is wrong in plain words, and what to do about it.
/// </summary>
/// <remarks>
/// On Unix every failed open is an <see cref="UnauthorizedAccessException"/> ("Access to the port is denied", even for
/// a missing file) wrapping an <see cref="IOException"/> whose <see cref="Exception.HResult"/> is the <c>errno</c>; a
/// refused termios setting is a bare <see cref="ArgumentException"/>. On Windows a missing port is an
/// <see cref="IOException"/>, a port held by another program an <see cref="UnauthorizedAccessException"/>, and refused
/// settings an <see cref="IOException"/> with ERROR_INVALID_PARAMETER. The errno of the first failure in a process is
/// not always right, so a missing path is recognised by looking for it.
/// </remarks>
internal static class SerialOpenFailure
{
    private const int EPERM = 1;
    private const int ENOENT = 2;
    private const int EIO = 5;
    private const int ENXIO = 6;
    private const int EACCES = 13;
    private const int EBUSY = 16;
    private const int ENODEV = 19;
    private const int ENOTTY = 25;
    private const int WindowsInvalidParameter = unchecked((int)0x80070057);

    /// <summary>What was being done when the port failed.</summary>
    public enum Stage
    {
        /// <summary>Opening the device and applying the line settings.</summary>
        Open,

        /// <summary>Raising DTR (<see cref="SerialLineSettings.DtrEnable"/>).</summary>
        RaiseDtr,

        /// <summary>Raising RTS (<see cref="SerialLineSettings.RtsEnable"/>).</summary>
        RaiseRts,
    }

    /// <summary>Whether <paramref name="e"/> is how System.IO.Ports reports a port that cannot be opened or configured.</summary>
    public static bool Is(Exception e)
        => e is IOException or UnauthorizedAccessException or ArgumentException or InvalidOperationException or PlatformNotSupportedException;

    /// <summary>The exception to throw for <paramref name="error"/>.</summary>
    public static HostLinkConnectionException Describe(SerialLineSettings settings, Exception error, Stage stage)
        => Describe(settings, error, stage, RuntimeInformation.IsOSPlatform(OSPlatform.Windows), File.Exists);

    /// <summary>The same, with the platform and the existence check given (for tests).</summary>
    internal static HostLinkConnectionException Describe(SerialLineSettings settings, Exception error, Stage stage, bool windows, Func<string, bool> exists)
    {
        string name = settings.PortName;
        string reason = stage switch
        {
            Stage.RaiseDtr => ModemLine("DTR", "DtrEnable", error),
            Stage.RaiseRts => ModemLine("RTS", "RtsEnable", error),
            _ when error is PlatformNotSupportedException =>
                $"serial ports are not supported on this platform ({RuntimeInformation.OSDescription}). Use a TCP serial-device server (HostLinkClient.ForTcp) instead",
            _ => windows ? OnWindows(settings, error) : OnUnix(settings, error, exists),
        };
        return new HostLinkConnectionException($"Cannot open serial port {name}: {reason}.", error);
    }

    private static string OnUnix(SerialLineSettings settings, Exception error, Func<string, bool> exists)
    {
        if (error is ArgumentException)
        {
            return Refused(settings);
        }

        if (!exists(settings.PortName))
        {
            return NotFound(windows: false);
        }

        IOException? io = error as IOException ?? error.InnerException as IOException;
        return io?.HResult switch
        {
            ENOENT => NotFound(windows: false),
            EACCES or EPERM =>
                "permission denied. Add the user to the group that owns the device (usually dialout: sudo usermod -aG dialout $USER, then log in again)",
            EBUSY => InUse("it is in use by another program"),
            ENOTTY => "it is not a serial device. Give the path of a serial port (/dev/ttyUSB0, /dev/ttyS0) or a pseudo-terminal",
            ENXIO or ENODEV or EIO => "no device answers behind it (unplugged, or its driver failed). Check that the adapter is plugged in",
            _ => Plain(io ?? error),
        };
    }

    private static string OnWindows(SerialLineSettings settings, Exception error)
    {
        return error switch
        {
            UnauthorizedAccessException => InUse("access is denied: it is most likely in use by another program"),
            ArgumentException => "this is not a serial port name. Use the port's COM name, such as COM3",
            IOException { HResult: WindowsInvalidParameter } => Refused(settings),
            IOException when !Listed(settings.PortName) => NotFound(windows: true),
            _ => Plain(error),
        };
    }

    private static string NotFound(bool windows) => windows
        ? "it does not exist. Check that the adapter is plugged in and the port's COM number in Device Manager (Ports (COM & LPT))"
        : "it does not exist. Check that the device is plugged in and the path is right (ls /dev/ttyUSB* /dev/ttyACM* /dev/serial/by-id/)";

    private static string InUse(string what)
        => $"{what}. Close the other program (a terminal, another hostlink, the worker service) and try again";

    private static string Refused(SerialLineSettings settings)
        => $"the device refused the line settings {LineSettings(settings)}. Check that the adapter supports them (some USB adapters lack 7 data bits or 2 stop bits)";

    private static string ModemLine(string line, string option, Exception error)
        => $"cannot raise {line} ({Plain(error)}). Turn {option} off: pseudo-terminals and some adapters have no modem-control lines";

    /// <summary>The operating system's words, without the port name System.IO.Ports sometimes puts in them.</summary>
    private static string Plain(Exception error)
    {
        Exception e = error is UnauthorizedAccessException { InnerException: IOException inner } ? inner : error;
        return e.Message.Trim().TrimEnd('.');
    }

    private static string LineSettings(SerialLineSettings settings)
    {
        string text = settings.ToString();
        return text.StartsWith(settings.PortName + " ", StringComparison.Ordinal) ? text.Substring(settings.PortName.Length + 1) : text;
    }

    private static bool Listed(string portName)
    {
        try
        {
            return Array.Exists(System.IO.Ports.SerialPort.GetPortNames(), p => string.Equals(p, portName, StringComparison.OrdinalIgnoreCase));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or PlatformNotSupportedException or System.Security.SecurityException)
        {
            return true;
        }
    }
}
