using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>
/// glibc/Linux declarations used by <see cref="LinuxSerialStream"/>. Values are those of the generic Linux ABI
/// (x86, x86_64, arm, arm64, riscv64, loongarch64), checked against /usr/include/x86_64-linux-gnu/bits/termios*.h,
/// asm-generic/termbits*.h, asm-generic/ioctls.h, asm-generic/fcntl.h and asm-generic/poll.h.
/// Other architectures (powerpc, mips, sparc, alpha) and other Unix systems use different values.
/// </summary>
internal static unsafe class LinuxNative
{
    private const string Libc = "libc";

    // fcntl.h
    public const int O_RDWR = 0x2;           // 02
    public const int O_NOCTTY = 0x100;       // 0400
    public const int O_NONBLOCK = 0x800;     // 04000
    public const int O_CLOEXEC = 0x80000;    // 02000000

    // sys/eventfd.h
    public const int EFD_NONBLOCK = 0x800;   // 04000
    public const int EFD_CLOEXEC = 0x80000;  // 02000000

    // poll.h
    public const short POLLIN = 0x001;
    public const short POLLOUT = 0x004;
    public const short POLLERR = 0x008;
    public const short POLLHUP = 0x010;
    public const short POLLNVAL = 0x020;

    // errno
    public const int EPERM = 1;
    public const int ENOENT = 2;
    public const int EINTR = 4;
    public const int EIO = 5;
    public const int ENXIO = 6;
    public const int EAGAIN = 11;
    public const int EACCES = 13;
    public const int EBUSY = 16;
    public const int ENODEV = 19;
    public const int EISDIR = 21;
    public const int EINVAL = 22;
    public const int ENOTTY = 25;
    public const int ELOOP = 40;

    // termios c_iflag
    public const uint IGNBRK = 0x001;
    public const uint BRKINT = 0x002;
    public const uint IGNPAR = 0x004;
    public const uint PARMRK = 0x008;
    public const uint INPCK = 0x010;
    public const uint ISTRIP = 0x020;
    public const uint INLCR = 0x040;
    public const uint IGNCR = 0x080;
    public const uint ICRNL = 0x100;
    public const uint IUCLC = 0x200;
    public const uint IXON = 0x400;
    public const uint IXANY = 0x800;
    public const uint IXOFF = 0x1000;
    public const uint IMAXBEL = 0x2000;

    // termios c_oflag
    public const uint OPOST = 0x01;

    // termios c_cflag
    public const uint CBAUD = 0x100F;        // 010017
    public const uint CSIZE = 0x30;          // 060
    public const uint CS7 = 0x20;            // 040
    public const uint CS8 = 0x30;            // 060
    public const uint CSTOPB = 0x40;         // 0100
    public const uint CREAD = 0x80;          // 0200
    public const uint PARENB = 0x100;        // 0400
    public const uint PARODD = 0x200;        // 01000
    public const uint CLOCAL = 0x800;        // 04000
    public const uint CRTSCTS = 0x80000000;  // 020000000000

    // termios c_lflag
    public const uint ISIG = 0x01;
    public const uint ICANON = 0x02;
    public const uint ECHO = 0x08;
    public const uint ECHOE = 0x10;
    public const uint ECHOK = 0x20;
    public const uint ECHONL = 0x40;
    public const uint IEXTEN = 0x8000;       // 0100000

    // termios c_cc indices
    public const int VTIME = 5;
    public const int VMIN = 6;
    public const int VSTART = 8;
    public const int VSTOP = 9;

    // tcsetattr / tcflush
    public const int TCSANOW = 0;
    public const int TCIFLUSH = 0;

    // ioctl
    public const nuint TIOCMBIS = 0x5416;
    public const nuint TIOCMBIC = 0x5417;
    public const int TIOCM_DTR = 0x002;
    public const int TIOCM_RTS = 0x004;

    /// <summary>glibc's <c>struct termios</c> on the generic Linux ABI: 60 bytes, c_cc at offset 17, c_ispeed at 52.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Termios
    {
        public uint c_iflag;
        public uint c_oflag;
        public uint c_cflag;
        public uint c_lflag;
        public byte c_line;
        public fixed byte c_cc[32];
        public uint c_ispeed;
        public uint c_ospeed;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct PollFd
    {
        public int fd;
        public short events;
        public short revents;
    }

    /// <summary>The termios speed constant (Bnnn) for a standard baud rate, or 0 when there is none.</summary>
    public static uint BaudConstant(int baudRate) => baudRate switch
    {
        300 => 0x7,         // B300    0000007
        600 => 0x8,         // B600    0000010
        1200 => 0x9,        // B1200   0000011
        1800 => 0xA,        // B1800   0000012
        2400 => 0xB,        // B2400   0000013
        4800 => 0xC,        // B4800   0000014
        9600 => 0xD,        // B9600   0000015
        19200 => 0xE,       // B19200  0000016
        38400 => 0xF,       // B38400  0000017
        57600 => 0x1001,    // B57600  0010001
        115200 => 0x1002,   // B115200 0010002
        230400 => 0x1003,   // B230400 0010003
        _ => 0,
    };

    [DllImport(Libc, EntryPoint = "open", SetLastError = true)]
    public static extern int Open(byte* path, int flags);

    [DllImport(Libc, EntryPoint = "close", SetLastError = true)]
    public static extern int Close(int fd);

    [DllImport(Libc, EntryPoint = "read", SetLastError = true)]
    public static extern nint Read(int fd, byte* buffer, nuint count);

    [DllImport(Libc, EntryPoint = "write", SetLastError = true)]
    public static extern nint Write(int fd, byte* buffer, nuint count);

    [DllImport(Libc, EntryPoint = "poll", SetLastError = true)]
    public static extern int Poll(PollFd* fds, nuint nfds, int timeout);

    [DllImport(Libc, EntryPoint = "eventfd", SetLastError = true)]
    public static extern int EventFd(uint initialValue, int flags);

    [DllImport(Libc, EntryPoint = "tcgetattr", SetLastError = true)]
    public static extern int TcGetAttr(int fd, Termios* termios);

    [DllImport(Libc, EntryPoint = "tcsetattr", SetLastError = true)]
    public static extern int TcSetAttr(int fd, int optionalActions, Termios* termios);

    [DllImport(Libc, EntryPoint = "cfsetispeed", SetLastError = true)]
    public static extern int CfSetISpeed(Termios* termios, uint speed);

    [DllImport(Libc, EntryPoint = "cfsetospeed", SetLastError = true)]
    public static extern int CfSetOSpeed(Termios* termios, uint speed);

    [DllImport(Libc, EntryPoint = "tcflush", SetLastError = true)]
    public static extern int TcFlush(int fd, int queueSelector);

    [DllImport(Libc, EntryPoint = "ioctl", SetLastError = true)]
    public static extern int Ioctl(int fd, nuint request, int* argument);

    [DllImport(Libc, EntryPoint = "strerror")]
    private static extern IntPtr StrError(int errno);

    /// <summary>A short description of an errno value in the user's words, with its symbolic name.</summary>
    public static string Describe(int errno) => errno switch
    {
        ENOENT => "no such device (ENOENT)",
        EACCES => "permission denied; is the user in the group that owns the device, e.g. dialout? (EACCES)",
        EPERM => "operation not permitted (EPERM)",
        EBUSY => "the device is busy, probably in use by another program (EBUSY)",
        ENXIO => "no such device or address; the adapter may have been unplugged (ENXIO)",
        ENODEV => "no such device (ENODEV)",
        ENOTTY => "not a serial device (ENOTTY)",
        EISDIR => "it is a directory (EISDIR)",
        ELOOP => "too many levels of symbolic links (ELOOP)",
        EIO => "input/output error (EIO)",
        EINVAL => "invalid argument; the device refused the settings (EINVAL)",
        _ => $"{SystemMessage(errno)} (errno {errno})",
    };

    private static string SystemMessage(int errno)
    {
        try
        {
            IntPtr text = StrError(errno);
            return (text == IntPtr.Zero ? null : Marshal.PtrToStringAnsi(text)) ?? "unknown error";
        }
        catch (Exception ex) when (ex is DllNotFoundException or EntryPointNotFoundException)
        {
            return "unknown error";
        }
    }
}
