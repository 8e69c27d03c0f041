using System.ComponentModel;
using System.Runtime.InteropServices;
using System.Text;
using Microsoft.Win32.SafeHandles;

namespace OmronHostLink.Testing;

/// <summary>
/// A pseudo-terminal this process holds the master of (Linux): what is written to <see cref="Master"/> comes out of the
/// device at <see cref="Path"/>, which a program opens as a serial port. Unlike a <see cref="SocatPtyPair"/> the bytes
/// cross one pty and no other process, so they reach the reader as soon as the kernel hands them over.
/// </summary>
/// <remarks>
/// The terminal is put in raw mode, without echo, before anyone else opens it, so bytes written before its reader sets
/// its own mode are not echoed back. A write blocks while the terminal's buffer is full (its reader has stopped reading),
/// and closing the terminal does not end it: <see cref="Drain"/>, on a descriptor of the terminal this process keeps,
/// reads what is waiting, so the write goes on.
/// </remarks>
public sealed class PseudoTerminalMaster : IDisposable
{
    private const int ReadWrite = 0x2;
    private const int NoControllingTerminal = 0x100;
    private const int NonBlocking = 0x800;
    private const int SetNow = 0;

    private readonly SafeFileHandle _device;

    private PseudoTerminalMaster(FileStream master, SafeFileHandle device, string path)
    {
        Master = master;
        _device = device;
        Path = path;
    }

    /// <summary>The terminal's device (/dev/pts/N), for a reader to open.</summary>
    public string Path { get; }

    /// <summary>The master's end: what is written here comes out of <see cref="Path"/>.</summary>
    public FileStream Master { get; }

    /// <summary>Makes a pseudo-terminal in raw mode.</summary>
    /// <exception cref="Win32Exception">The system refused one of the steps (the message names it).</exception>
    public static PseudoTerminalMaster Open()
    {
        var master = new SafeFileHandle(Check(OpenMaster(ReadWrite | NoControllingTerminal), "posix_openpt"), ownsHandle: true);
        SafeFileHandle? device = null;
        try
        {
            Check(GrantPt(master), "grantpt");
            Check(UnlockPt(master), "unlockpt");
            var name = new byte[128];
            int error = PtsName(master, name, (nuint)name.Length);
            if (error != 0)
            {
                throw new Win32Exception(error, "ptsname_r failed");
            }

            string path = Encoding.ASCII.GetString(name, 0, Array.IndexOf(name, (byte)0));
            device = new SafeFileHandle(Check(OpenDevice(path, ReadWrite | NoControllingTerminal | NonBlocking), "open " + path), ownsHandle: true);
            var termios = new byte[256];
            Check(GetAttributes(device, termios), "tcgetattr");
            MakeRaw(termios);
            Check(SetAttributes(device, SetNow, termios), "tcsetattr");
            return new PseudoTerminalMaster(new FileStream(master, FileAccess.Write, bufferSize: 0), device, path);
        }
        catch
        {
            device?.Dispose();
            master.Dispose();
            throw;
        }
    }

    /// <summary>Reads and drops whatever is waiting to be read from the terminal, without waiting for more.</summary>
    public void Drain()
    {
        var buffer = new byte[4096];
        while (ReadDevice(_device, buffer, (nuint)buffer.Length) > 0)
        {
        }
    }

    /// <summary>Closes the terminal and the master: a reader's port hangs up.</summary>
    public void Dispose()
    {
        _device.Dispose();
        Master.Dispose();
    }

    private static int Check(int result, string what)
        => result >= 0 ? result : throw new Win32Exception(Marshal.GetLastPInvokeError(), what + " failed");

    [DllImport("libc", EntryPoint = "posix_openpt", SetLastError = true)]
    private static extern int OpenMaster(int flags);

    [DllImport("libc", EntryPoint = "grantpt", SetLastError = true)]
    private static extern int GrantPt(SafeFileHandle master);

    [DllImport("libc", EntryPoint = "unlockpt", SetLastError = true)]
    private static extern int UnlockPt(SafeFileHandle master);

    [DllImport("libc", EntryPoint = "ptsname_r")]
    private static extern int PtsName(SafeFileHandle master, byte[] buffer, nuint length);

    [DllImport("libc", EntryPoint = "open", SetLastError = true)]
    private static extern int OpenDevice([MarshalAs(UnmanagedType.LPStr)] string path, int flags);

    [DllImport("libc", EntryPoint = "read", SetLastError = true)]
    private static extern nint ReadDevice(SafeFileHandle device, byte[] buffer, nuint count);

    [DllImport("libc", EntryPoint = "tcgetattr", SetLastError = true)]
    private static extern int GetAttributes(SafeFileHandle device, byte[] termios);

    [DllImport("libc", EntryPoint = "cfmakeraw")]
    private static extern void MakeRaw(byte[] termios);

    [DllImport("libc", EntryPoint = "tcsetattr", SetLastError = true)]
    private static extern int SetAttributes(SafeFileHandle device, int when, byte[] termios);
}
