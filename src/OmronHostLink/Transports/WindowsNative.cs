using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;

namespace OmronHostLink.Transports;

/// <summary>kernel32 declarations used by <see cref="WindowsSerialStream"/> (values from winbase.h / winerror.h).</summary>
/// <remarks>Exercised only on Windows; the Linux CI builds this code but cannot run it.</remarks>
internal static class WindowsNative
{
    private const string Kernel32 = "kernel32.dll";

    public const uint GENERIC_READ = 0x80000000;
    public const uint GENERIC_WRITE = 0x40000000;
    public const uint OPEN_EXISTING = 3;
    public const uint FILE_FLAG_OVERLAPPED = 0x40000000;

    public const uint MAXDWORD = 0xFFFFFFFF;

    public const uint PURGE_RXCLEAR = 0x0008;

    public const byte NOPARITY = 0;
    public const byte ODDPARITY = 1;
    public const byte EVENPARITY = 2;
    public const byte ONESTOPBIT = 0;
    public const byte TWOSTOPBITS = 2;

    // DCB bit fields, packed into DCB.Flags.
    public const uint fBinary = 0x0001;
    public const uint fParity = 0x0002;
    public const uint fOutxCtsFlow = 0x0004;
    public const uint fOutxDsrFlow = 0x0008;
    public const uint fDtrControlMask = 0x0030;   // 2 bits at bit 4
    public const uint fDtrControlEnable = 0x0010; // DTR_CONTROL_ENABLE << 4
    public const uint fDsrSensitivity = 0x0040;
    public const uint fTXContinueOnXoff = 0x0080;
    public const uint fOutX = 0x0100;
    public const uint fInX = 0x0200;
    public const uint fErrorChar = 0x0400;
    public const uint fNull = 0x0800;
    public const uint fRtsControlMask = 0x3000;   // 2 bits at bit 12
    public const uint fRtsControlEnable = 0x1000; // RTS_CONTROL_ENABLE << 12
    public const uint fRtsControlHandshake = 0x2000; // RTS_CONTROL_HANDSHAKE << 12
    public const uint fAbortOnError = 0x4000;

    public const int ERROR_FILE_NOT_FOUND = 2;
    public const int ERROR_PATH_NOT_FOUND = 3;
    public const int ERROR_ACCESS_DENIED = 5;
    public const int ERROR_INVALID_HANDLE = 6;
    public const int ERROR_SHARING_VIOLATION = 32;
    public const int ERROR_INVALID_PARAMETER = 87;
    public const int ERROR_SEM_TIMEOUT = 121;
    public const int ERROR_DEVICE_NOT_CONNECTED = 1167;
    public const int ERROR_GEN_FAILURE = 31;

    [StructLayout(LayoutKind.Sequential)]
    public struct Dcb
    {
        public uint DCBlength;
        public uint BaudRate;
        public uint Flags;
        public ushort wReserved;
        public ushort XonLim;
        public ushort XoffLim;
        public byte ByteSize;
        public byte Parity;
        public byte StopBits;
        public byte XonChar;
        public byte XoffChar;
        public byte ErrorChar;
        public byte EofChar;
        public byte EvtChar;
        public ushort wReserved1;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct CommTimeouts
    {
        public uint ReadIntervalTimeout;
        public uint ReadTotalTimeoutMultiplier;
        public uint ReadTotalTimeoutConstant;
        public uint WriteTotalTimeoutMultiplier;
        public uint WriteTotalTimeoutConstant;
    }

    [DllImport(Kernel32, EntryPoint = "CreateFileW", CharSet = CharSet.Unicode, SetLastError = true)]
    public static extern SafeFileHandle CreateFile(
        string fileName, uint desiredAccess, uint shareMode, IntPtr securityAttributes,
        uint creationDisposition, uint flagsAndAttributes, IntPtr templateFile);

    [DllImport(Kernel32, SetLastError = true)]
    [return: MarshalAs(UnmanagedType.Bool)]
    public static extern bool GetCommState(SafeFileHandle file, ref Dcb dcb);

    [DllImport(Kernel32, SetLastError = true)]
    [return: MarshalAs(UnmanagedType.Bool)]
    public static extern bool SetCommState(SafeFileHandle file, ref Dcb dcb);

    [DllImport(Kernel32, SetLastError = true)]
    [return: MarshalAs(UnmanagedType.Bool)]
    public static extern bool SetCommTimeouts(SafeFileHandle file, ref CommTimeouts timeouts);

    [DllImport(Kernel32, SetLastError = true)]
    [return: MarshalAs(UnmanagedType.Bool)]
    public static extern bool PurgeComm(SafeFileHandle file, uint flags);

    /// <summary>A short description of a Win32 error code with its symbolic name.</summary>
    public static string Describe(int error) => error switch
    {
        ERROR_FILE_NOT_FOUND or ERROR_PATH_NOT_FOUND => "no such port (ERROR_FILE_NOT_FOUND)",
        ERROR_ACCESS_DENIED => "access denied; the port is probably open in another program (ERROR_ACCESS_DENIED)",
        ERROR_SHARING_VIOLATION => "the port is in use by another program (ERROR_SHARING_VIOLATION)",
        ERROR_INVALID_HANDLE => "not a serial port (ERROR_INVALID_HANDLE)",
        ERROR_INVALID_PARAMETER => "the driver refused the settings (ERROR_INVALID_PARAMETER)",
        ERROR_SEM_TIMEOUT => "the device did not respond (ERROR_SEM_TIMEOUT)",
        ERROR_GEN_FAILURE => "the device is not functioning; it may have been unplugged (ERROR_GEN_FAILURE)",
        ERROR_DEVICE_NOT_CONNECTED => "the device is not connected (ERROR_DEVICE_NOT_CONNECTED)",
        _ => $"{new System.ComponentModel.Win32Exception(error).Message} (Win32 error {error})",
    };
}
