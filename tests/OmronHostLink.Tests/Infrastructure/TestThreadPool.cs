using System.Runtime.CompilerServices;

namespace OmronHostLink.Tests.Infrastructure;

/// <summary>
/// Raises the thread pool's minimum for the test process. Under the xUnit host on a 2-core machine the pool starts with
/// 2-3 workers and the runner's own work can hold them; the pool then adds a thread only every ~500 ms, so a deadline
/// timer or an in-process simulator's answer waits half a second (measured: 1 stall in ~3,000 exchanges in the test
/// host, none in 30,000 with the same client and simulator in a plain console process).
/// </summary>
internal static class TestThreadPool
{
    [ModuleInitializer]
    internal static void Raise()
    {
        ThreadPool.GetMinThreads(out int workers, out int io);
        ThreadPool.SetMinThreads(Math.Max(workers, 16), Math.Max(io, 16));
    }
}
