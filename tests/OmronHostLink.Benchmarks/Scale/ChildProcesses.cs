using System.Diagnostics;

namespace OmronHostLink.Benchmarks.Scale;

/// <summary>
/// The processes the benchmark has started (worker, broker): ended when the benchmark ends, however it ends — normally,
/// by an exception, by Ctrl+C or by SIGTERM (their normal stop paths run; this is the last resort at process exit).
/// </summary>
internal static class ChildProcesses
{
    private static readonly List<Process> Running = new();

    static ChildProcesses()
    {
        AppDomain.CurrentDomain.ProcessExit += (_, _) => KillAll();
    }

    public static void Add(Process process)
    {
        lock (Running)
        {
            Running.Add(process);
        }
    }

    public static void Remove(Process process)
    {
        lock (Running)
        {
            Running.Remove(process);
        }
    }

    private static void KillAll()
    {
        Process[] left;
        lock (Running)
        {
            left = Running.ToArray();
            Running.Clear();
        }

        foreach (Process process in left)
        {
            try
            {
                if (!process.HasExited)
                {
                    process.Kill(entireProcessTree: true);
                }
            }
            catch (InvalidOperationException)
            {
            }
        }
    }
}
