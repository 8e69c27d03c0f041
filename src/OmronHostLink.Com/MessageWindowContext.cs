using System.Collections.Concurrent;
using System.Runtime.InteropServices;

namespace OmronHostLink.Com;

/// <summary>
/// A <see cref="SynchronizationContext"/> whose callbacks run on the thread that created it, the way a VB6 form's or a
/// script's events must: posted to a message-only window of that thread, and run when the thread dispatches its
/// messages (a form's message loop, VBA between macros' statements that yield, <c>WScript.Sleep</c>). A COM caller's
/// thread has no synchronization context of its own to capture.
/// </summary>
/// <remarks>Create, use and <see cref="Dispose"/> it on the same thread: a window belongs to the thread that made it.</remarks>
internal sealed class MessageWindowContext : SynchronizationContext, IDisposable
{
    private const uint RunQueued = NativeMethods.WmApp + 1;
    private const string ClassName = "OmronHostLink.Com.MessageWindow";

    private static readonly ConcurrentDictionary<nint, MessageWindowContext> Windows = new();
    private static readonly Lazy<bool> ClassRegistered = new(RegisterClass);

    private readonly ConcurrentQueue<(SendOrPostCallback Callback, object? State)> _queue = new();
    private nint _window;

    /// <summary>Creates the window on the calling thread.</summary>
    /// <exception cref="InvalidOperationException">Windows refused the window.</exception>
    public MessageWindowContext()
    {
        _ = ClassRegistered.Value;
        _window = NativeMethods.CreateWindowEx(0, ClassName, null, 0, 0, 0, 0, 0, NativeMethods.HwndMessage, 0, NativeMethods.GetModuleHandle(null), 0);
        if (_window == 0)
        {
            throw new InvalidOperationException($"Windows refused the message window that carries events to this thread (error {Marshal.GetLastPInvokeError()}).");
        }

        ThreadId = NativeMethods.GetCurrentThreadId();
        Windows[_window] = this;
    }

    /// <summary>The Win32 id of the thread the callbacks run on.</summary>
    public uint ThreadId { get; }

    /// <summary>Queues <paramref name="d"/> to run on the window's thread; dropped once the context is disposed.</summary>
    public override void Post(SendOrPostCallback d, object? state)
    {
        nint window = _window;
        if (window == 0)
        {
            return;
        }

        _queue.Enqueue((d, state));
        NativeMethods.PostMessage(window, RunQueued, 0, 0);
    }

    /// <summary>Not supported: a caller waiting for a thread that waits for it would deadlock.</summary>
    public override void Send(SendOrPostCallback d, object? state)
        => throw new NotSupportedException("The COM server only posts to its caller's thread.");

    /// <inheritdoc />
    public override SynchronizationContext CreateCopy() => this;

    /// <summary>Destroys the window; queued callbacks that have not run are dropped.</summary>
    public void Dispose()
    {
        nint window = _window;
        _window = 0;
        if (window != 0)
        {
            Windows.TryRemove(window, out _);
            NativeMethods.DestroyWindow(window);
        }

        _queue.Clear();
    }

    private void RunQueue()
    {
        SynchronizationContext? previous = Current;
        SetSynchronizationContext(this);
        try
        {
            while (_window != 0 && _queue.TryDequeue(out (SendOrPostCallback Callback, object? State) item))
            {
                item.Callback(item.State);
            }
        }
        finally
        {
            SetSynchronizationContext(previous);
        }
    }

    private static unsafe bool RegisterClass()
    {
        fixed (char* name = ClassName)
        {
            var windowClass = new NativeMethods.WindowClass
            {
                Size = (uint)sizeof(NativeMethods.WindowClass),
                WindowProcedure = &WindowProcedure,
                Instance = NativeMethods.GetModuleHandle(null),
                ClassName = name,
            };
            if (NativeMethods.RegisterClassEx(windowClass) == 0)
            {
                throw new InvalidOperationException($"Windows refused the message window class (error {Marshal.GetLastPInvokeError()}).");
            }
        }

        return true;
    }

    [UnmanagedCallersOnly]
    private static nint WindowProcedure(nint window, uint message, nint wParam, nint lParam)
    {
        if (message == RunQueued && Windows.TryGetValue(window, out MessageWindowContext? context))
        {
            try
            {
                context.RunQueue();
            }
            catch (Exception e)
            {
                // An exception must not unwind into the caller's message loop; the watch reports handler failures
                // itself, so this is a failure of the server, kept where a debugger or a crash dump finds it.
                Environment.FailFast("OmronHostLink.Com: an event callback failed.", e);
            }

            return 0;
        }

        return NativeMethods.DefWindowProc(window, message, wParam, lParam);
    }
}
