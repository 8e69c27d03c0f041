using System.Runtime.InteropServices;

namespace OmronHostLink.Transports;

/// <summary>
/// Owns a Unix file descriptor. Every system call on it holds a reference (<see cref="SafeHandle.DangerousAddRef"/>),
/// so disposing while a read is parked in <c>poll()</c> defers <c>close()</c> until that call has returned:
/// the descriptor number can never be reused by someone else while we still use it.
/// </summary>
internal sealed class FileDescriptorHandle : SafeHandle
{
    public FileDescriptorHandle(int fd)
        : base(new IntPtr(-1), ownsHandle: true)
        => SetHandle(new IntPtr(fd));

    public override bool IsInvalid => handle.ToInt64() < 0;

    /// <summary>The descriptor number; call only while holding a reference.</summary>
    public int Fd => (int)handle.ToInt64();

    protected override bool ReleaseHandle() => LinuxNative.Close(Fd) == 0;
}
