using System.Diagnostics;
using System.Runtime.InteropServices;

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

    /// <summary>Asks <paramref name="process"/> to stop (SIGTERM), waits up to <paramref name="patience"/>, then kills it.</summary>
    /// <returns>Whether it stopped by itself.</returns>
    public static async Task<bool> StopAsync(Process process, TimeSpan patience)
    {
        bool graceful = true;
        try
        {
            if (!process.HasExited)
            {
                _ = Kill(process.Id, 15);
                using var timeout = new CancellationTokenSource(patience);
                try
                {
                    await process.WaitForExitAsync(timeout.Token).ConfigureAwait(false);
                }
                catch (OperationCanceledException)
                {
                    graceful = false;
                    process.Kill(entireProcessTree: true);
                    await process.WaitForExitAsync().WaitAsync(TimeSpan.FromSeconds(5)).ConfigureAwait(ConfigureAwaitOptions.SuppressThrowing);
                }
            }
        }
        catch (InvalidOperationException)
        {
            // Never started or already gone.
        }

        Remove(process);
        return graceful;
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

    [DllImport("libc", EntryPoint = "kill", SetLastError = true)]
    private static extern int Kill(int pid, int signal);
}
