using System.Runtime.InteropServices;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Real-time scheduling (SCHED_FIFO) for the monitor's threads on Linux, where it is allowed (root, CAP_SYS_NICE or an
/// rtprio limit); elsewhere nothing changes. A port's reader sleeps in poll and read and takes almost no processor time,
/// so a timestamp it takes when it wakes is not held back by other processes keeping the processors busy; the thread
/// that pairs and prints runs so too, because a garbage collection runs on the thread that needs it, and every thread of
/// the process (the readers too) waits for it to end.
/// </summary>
internal static class RealTimeScheduling
{
    private const int SchedFifo = 1;
    private const int Priority = 10;

    /// <summary>Raises the calling thread; false when not allowed or not on Linux.</summary>
    public static bool TryRaiseThisThread()
    {
        if (!RuntimeInformation.IsOSPlatform(OSPlatform.Linux))
        {
            return false;
        }

        var param = new SchedParam { Priority = Priority };
        return SetScheduler(0, SchedFifo, ref param) == 0;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct SchedParam
    {
        public int Priority;
    }

    [DllImport("libc", EntryPoint = "sched_setscheduler", SetLastError = true)]
    private static extern int SetScheduler(int pid, int policy, ref SchedParam param);
}
