using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>
/// Opens serial ports as <see cref="Stream"/>s without System.IO.Ports: on Linux over termios and a non-blocking
/// file descriptor, on Windows over kernel32 comm functions and overlapped I/O.
/// </summary>
public static class SerialPortStream
{
    /// <summary>
    /// Opens the port, applies the line settings and returns it as a stream whose ReadAsync and WriteAsync are truly
    /// asynchronous and honour their <see cref="CancellationToken"/>. The stream also implements
    /// <see cref="IInputDiscardable"/>.
    /// </summary>
    /// <remarks>
    /// <para>A read returns as soon as at least one byte has arrived. On Linux a read or write whose token fires completes
    /// promptly with <see cref="OperationCanceledException"/>, and the stream stays usable; a write cancelled part-way
    /// may have sent some of its bytes. Disposing the stream completes a pending read or write with
    /// <see cref="ObjectDisposedException"/> (on Windows, possibly <see cref="OperationCanceledException"/>).</para>
    /// <para>When the device goes away (a USB adapter unplugged, the other end of a pseudo-terminal closed) reads and
    /// writes fail with <see cref="IOException"/> instead of returning 0 bytes.</para>
    /// <para>Supported on Linux (x86, x64, arm, arm64, riscv64, loongarch64) and Windows.</para>
    /// </remarks>
    /// <param name="settings">The port name and line settings; checked with <see cref="SerialLineSettings.Validate"/>.</param>
    /// <returns>The open port. Dispose it to close the port.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="settings"/> is null.</exception>
    /// <exception cref="ArgumentException">A setting is invalid.</exception>
    /// <exception cref="SerialPortUnavailableException">The port does not exist, is in use, is not a serial device,
    /// access is denied, or it refused the settings.</exception>
    /// <exception cref="PlatformNotSupportedException">The operating system or processor architecture is not supported.</exception>
    public static Stream Open(SerialLineSettings settings)
    {
        Guard.NotNull(settings);
        settings.Validate();

        if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
        {
            return WindowsSerialStream.Open(settings);
        }

        if (RuntimeInformation.IsOSPlatform(OSPlatform.Linux))
        {
            if (!LinuxSerialStream.IsSupportedArchitecture)
            {
                throw new PlatformNotSupportedException(
                    $"Serial ports are not supported on Linux/{RuntimeInformation.ProcessArchitecture}: its termios layout differs from the one this library uses. Use a TCP serial-device server instead.");
            }

            return LinuxSerialStream.Open(settings);
        }

        throw new PlatformNotSupportedException(
            $"Serial ports are supported on Linux and Windows only, not on {RuntimeInformation.OSDescription}. Use a TCP serial-device server instead.");
    }

    /// <summary>
    /// Lists the serial ports that exist. On Linux: <c>/dev/ttyS*</c>, <c>/dev/ttyUSB*</c>, <c>/dev/ttyACM*</c> and
    /// <c>/dev/serial/by-id/*</c> (pseudo-terminals are never listed; <c>/dev/ttyS*</c> nodes often exist without hardware
    /// behind them). On Windows, built for .NET 5 or later: the names in <c>HKLM\HARDWARE\DEVICEMAP\SERIALCOMM</c>; the
    /// netstandard2.0 build has no registry access without an extra package and returns an empty list there.
    /// Other systems: an empty list.
    /// </summary>
    /// <returns>The port names, sorted; possibly empty.</returns>
    public static IReadOnlyList<string> GetPortNames()
    {
        var names = new List<string>();
        if (RuntimeInformation.IsOSPlatform(OSPlatform.Linux))
        {
            AddMatches(names, "/dev", "ttyS*");
            AddMatches(names, "/dev", "ttyUSB*");
            AddMatches(names, "/dev", "ttyACM*");
            AddMatches(names, "/dev/serial/by-id", "*");
        }
#if NET
        else if (OperatingSystem.IsWindows())
        {
            using var key = Microsoft.Win32.Registry.LocalMachine.OpenSubKey(@"HARDWARE\DEVICEMAP\SERIALCOMM");
            if (key is not null)
            {
                foreach (string valueName in key.GetValueNames())
                {
                    if (key.GetValue(valueName) is string port && port.Length > 0)
                    {
                        names.Add(port);
                    }
                }
            }
        }
#endif

        names.Sort(StringComparer.Ordinal);
        return names;
    }

    private static void AddMatches(List<string> names, string directory, string pattern)
    {
        try
        {
            if (Directory.Exists(directory))
            {
                foreach (string path in Directory.EnumerateFileSystemEntries(directory, pattern))
                {
                    if (File.Exists(path))
                    {
                        names.Add(path);
                    }
                }
            }
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            // A directory we may not list is simply skipped.
        }
    }
}
