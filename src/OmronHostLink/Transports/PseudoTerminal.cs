using System.Reflection;
using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>
/// Recognises a pseudo-terminal (a pty, such as either end of a socat pair) by the device its name leads to.
/// </summary>
/// <remarks>
/// A pty has no line: it carries 8-bit bytes whatever its termios says, ignores baud rate and parity, and on some Linux
/// kernels refuses any change of data bits or parity once its first user has closed it (EINVAL). So a pty is opened
/// with the data bits and parity it holds (8, none) instead of the user's, and the link keeps timing its deadlines from
/// the user's settings. The check reads no termios and makes no ioctl: it follows symbolic links (socat's
/// <c>link=</c>) and looks at the device path: <c>/dev/pts/N</c> on Linux, <c>/dev/ttysNNN</c> on macOS.
/// </remarks>
internal static class PseudoTerminal
{
#if !NET
    // The netstandard2.0 build runs on .NET 6 or later on Linux (a .NET 8 application picks it): use File.ResolveLinkTarget
    // where the runtime has it; elsewhere only a direct /dev/pts path is recognised.
    private static readonly MethodInfo? ResolveLinkTarget =
        typeof(File).GetMethod("ResolveLinkTarget", BindingFlags.Public | BindingFlags.Static, null, [typeof(string), typeof(bool)], null);
#endif

    /// <summary>Whether <paramref name="portName"/> is, or links to, a pseudo-terminal.</summary>
    public static bool Is(string portName) => IsDevicePath(DevicePath(portName));

    /// <summary>Whether the device path names a pseudo-terminal's terminal side.</summary>
    internal static bool IsDevicePath(string path)
    {
        if (path.StartsWith("/dev/pts/", StringComparison.Ordinal))
        {
            return path.Length > "/dev/pts/".Length && AllDigits(path, "/dev/pts/".Length);
        }

        // macOS and the BSDs name the terminal side of a pty /dev/ttysNNN (serial ports are /dev/tty.* and /dev/cu.*).
        return path.StartsWith("/dev/ttys", StringComparison.Ordinal)
            && path.Length > "/dev/ttys".Length
            && AllDigits(path, "/dev/ttys".Length);
    }

    /// <summary>The path <paramref name="portName"/> finally leads to after every symbolic link; the name itself on Windows or when it cannot be followed.</summary>
    internal static string DevicePath(string portName)
    {
        if (RuntimeInformation.IsOSPlatform(OSPlatform.Windows))
        {
            return portName;
        }

        try
        {
#if NET
            return File.ResolveLinkTarget(portName, returnFinalTarget: true)?.FullName ?? Path.GetFullPath(portName);
#else
            if (ResolveLinkTarget?.Invoke(null, [portName, true]) is FileSystemInfo target)
            {
                return target.FullName;
            }

            return Path.GetFullPath(portName);
#endif
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException or TargetInvocationException)
        {
            // A missing path or a link we may not read: not a pty as far as we can tell; opening it reports the real problem.
            return portName;
        }
    }

    private static bool AllDigits(string text, int start)
    {
        for (int i = start; i < text.Length; i++)
        {
            if (text[i] is < '0' or > '9')
            {
                return false;
            }
        }

        return true;
    }
}
