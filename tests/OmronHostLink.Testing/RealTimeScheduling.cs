using System.Runtime.InteropServices;

namespace OmronHostLink.Testing;

/// <summary>
/// Asks Linux for real-time scheduling (SCHED_FIFO) for a thread or process that must run the moment its bytes come,
/// where it is allowed (root, CAP_SYS_NICE or an rtprio limit); elsewhere nothing changes. For timing tests on a busy
/// machine: a process of another test that keeps both cores busy then does not hold back a read by milliseconds.
/// </summary>
public static class RealTimeScheduling
{
    private const int SchedFifo = 1;

    /// <summary>Raises the calling thread (<paramref name="processOrThread"/> 0) or the given process; false when not allowed.</summary>
    public static bool TryRaise(int processOrThread = 0, int priority = 10)
    {
        if (!RuntimeInformation.IsOSPlatform(OSPlatform.Linux))
        {
            return false;
        }

        var param = new SchedParam { Priority = priority };
        return SetScheduler(processOrThread, SchedFifo, ref param) == 0;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct SchedParam
    {
        public int Priority;
    }

    [DllImport("libc", EntryPoint = "sched_setscheduler", SetLastError = true)]
    private static extern int SetScheduler(int pid, int policy, ref SchedParam param);
}
