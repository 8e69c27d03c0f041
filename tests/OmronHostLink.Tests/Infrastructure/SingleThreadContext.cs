using System.Collections.Concurrent;

namespace OmronHostLink.Tests.Infrastructure;

/// <summary>
/// A UI thread stand-in: one thread pumping a queue of callbacks, with itself installed as that thread's
/// <see cref="SynchronizationContext"/>, as a WinForms message loop is. A callback that blocks (a VB timer tick calling
/// <c>.Result</c>) blocks the pump, so anything that tries to resume on this context meanwhile waits for it: the
/// deadlock a library without <c>ConfigureAwait(false)</c> causes.
/// </summary>
internal sealed class SingleThreadContext : SynchronizationContext, IDisposable
{
    private readonly BlockingCollection<(SendOrPostCallback Callback, object? State)> _queue = new();
    private readonly Thread _thread;

    public SingleThreadContext()
    {
        _thread = new Thread(Pump) { IsBackground = true, Name = "UI thread stand-in" };
        _thread.Start();
    }

    /// <summary>
    /// Called with an exception a callback threw, as WinForms raises <c>Application.ThreadException</c> and goes on
    /// pumping; without it such an exception ends the pumping thread (and the process).
    /// </summary>
    public Action<Exception>? ThreadException { get; set; }

    /// <summary>The pumping thread's managed id.</summary>
    public int ThreadId => _thread.ManagedThreadId;

    public override void Post(SendOrPostCallback d, object? state) => _queue.Add((d, state));

    public override void Send(SendOrPostCallback d, object? state)
    {
        if (Environment.CurrentManagedThreadId == ThreadId)
        {
            d(state);
            return;
        }

        using var done = new ManualResetEventSlim();
        Exception? error = null;
        Post(
            _ =>
            {
                try
                {
                    d(state);
                }
                catch (Exception e)
                {
                    error = e;
                }
                finally
                {
                    done.Set();
                }
            },
            null);
        done.Wait();
        if (error is not null)
        {
            throw new AggregateException(error);
        }
    }

    /// <summary>Runs <paramref name="action"/> on the pumping thread; the task ends when it returns or throws.</summary>
    public Task Run(Action action)
    {
        var finished = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        Post(
            _ =>
            {
                try
                {
                    action();
                    finished.SetResult();
                }
                catch (Exception e)
                {
                    finished.SetException(e);
                }
            },
            null);
        return finished.Task;
    }

    /// <summary>
    /// Runs <paramref name="action"/> on the pumping thread; fails with <see cref="TimeoutException"/> if it has not
    /// returned within <paramref name="limit"/> (a deadlock: the thread is stuck and stays so).
    /// </summary>
    public Task Run(Action action, TimeSpan limit) => Run(action).WaitAsync(limit);

    public void Dispose() => _queue.CompleteAdding();

    private void Pump()
    {
        SetSynchronizationContext(this);
        foreach ((SendOrPostCallback callback, object? state) in _queue.GetConsumingEnumerable())
        {
            if (ThreadException is not { } report)
            {
                callback(state);
                continue;
            }

            try
            {
                callback(state);
            }
            catch (Exception e)
            {
                report(e);
            }
        }
    }
}
