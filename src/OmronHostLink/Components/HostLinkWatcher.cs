using System.Runtime.ExceptionServices;
using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// Watches tags and raises ordinary .NET events — <see cref="ValueChanged"/>, <see cref="ConnectionLost"/>,
/// <see cref="ConnectionRestored"/>, <see cref="Overrun"/> — on the <see cref="SynchronizationContext"/> that was current
/// when <see cref="Start"/> was called: started on a form's UI thread, the handlers run on it and can set a label's text.
/// It runs <see cref="IHostLinkUnit.WatchAsync(IReadOnlyList{PlcTag}, WatchOptions, CancellationToken)"/>, the library's
/// one polling engine: one planned read a cycle, changes against the values reported before, outages and retries.
/// </summary>
/// <remarks>
/// <para>
/// Each event's handlers run to the end before the watch goes on, so a slow handler slows the polling (and shows as
/// <see cref="Overrun"/>) rather than letting events pile up in the UI's queue. Without a synchronization context (a
/// console or a service) the handlers run on a thread-pool thread, one event at a time.
/// </para>
/// <para>
/// <b>An exception thrown by a handler never stops the watch.</b> It is passed to <see cref="Error"/> (with
/// <see cref="WatchErrorEventArgs.WatchEnded"/> false) and the watch goes on. With no <see cref="Error"/> handler, or
/// when that handler throws too, the exception is thrown on the captured context, as an exception from a WinForms
/// <c>Timer.Tick</c> handler is (WinForms shows it through <c>Application.ThreadException</c>, and the watch still goes
/// on); without a context it is thrown on a thread-pool thread, where, as any unhandled exception there, it ends the
/// process. Nothing is swallowed.
/// </para>
/// <para>
/// Link failures never end the watch (they are <see cref="ConnectionLost"/> and <see cref="ConnectionRestored"/>). Only
/// <see cref="Stop"/>, <see cref="Dispose"/>, or disposing the client ends it; the last is reported through
/// <see cref="Error"/> with <see cref="WatchErrorEventArgs.WatchEnded"/> true.
/// </para>
/// </remarks>
/// <example>
/// <code>
/// ' VB.NET, in a form: handlers run on the UI thread
/// Private WithEvents watcher As HostLinkWatcher
/// Private Sub Form1_Load(sender As Object, e As EventArgs) Handles MyBase.Load
///     watcher = New HostLinkWatcher(plc, {"D100:float", "CIO 10.03"}, TimeSpan.FromMilliseconds(500))
///     watcher.Start()
/// End Sub
/// Private Sub watcher_ValueChanged(sender As Object, e As TagValueChangedEventArgs) Handles watcher.ValueChanged
///     Label1.Text = e.TagText &amp; " = " &amp; e.NewValue.ToString()
/// End Sub
/// </code>
/// </example>
public sealed class HostLinkWatcher : IDisposable
{
    private readonly IHostLinkUnit _unit;
    private readonly string[] _tagTexts;
    private readonly PlcTag[] _tags;
    private readonly WatchOptions _options;
    private Run? _run;
    private bool _disposed;

    /// <summary>Creates a watcher of <paramref name="tags"/> read every <paramref name="interval"/>; nothing is read until <see cref="Start"/>.</summary>
    /// <param name="unit">The client or unit view to read from.</param>
    /// <param name="tags">Tags as text: <c>D100</c> (a word), <c>D100:float</c>, <c>D20:bcd</c>, <c>CIO 10.03</c> (a bit), <c>T5:bit</c>.</param>
    /// <param name="interval">From the start of one cycle to the start of the next; zero polls back to back.</param>
    /// <exception cref="FormatException">A tag is not valid; the message names it.</exception>
    /// <exception cref="ArgumentException">No tags.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="interval"/> is negative or over 1 day.</exception>
    public HostLinkWatcher(IHostLinkUnit unit, IEnumerable<string> tags, TimeSpan interval)
        : this(unit, tags, new WatchOptions { Interval = interval })
    {
    }

    /// <summary>Creates a watcher of <paramref name="tags"/> polled as <paramref name="options"/> say (interval, retry interval, clock).</summary>
    /// <param name="unit">The client or unit view to read from.</param>
    /// <param name="tags">Tags as text: <c>D100</c> (a word), <c>D100:float</c>, <c>D20:bcd</c>, <c>CIO 10.03</c> (a bit), <c>T5:bit</c>.</param>
    /// <param name="options">How to poll; copied.</param>
    /// <exception cref="FormatException">A tag is not valid; the message names it.</exception>
    /// <exception cref="ArgumentException">No tags.</exception>
    /// <exception cref="ArgumentOutOfRangeException">An option is out of range.</exception>
    public HostLinkWatcher(IHostLinkUnit unit, IEnumerable<string> tags, WatchOptions options)
    {
        _unit = Guard.NotNull(unit);
        _tagTexts = Guard.NotNull(tags).ToArray();
        Guard.NotNull(options).Validate();
        if (_tagTexts.Length == 0)
        {
            throw new ArgumentException("Give at least one tag to watch, such as \"D100\" or \"D100:float\".", nameof(tags));
        }

        _tags = Array.ConvertAll(_tagTexts, text => PlcTag.Parse(Guard.NotNull(text, nameof(tags))));
        _options = new WatchOptions
        {
            Interval = options.Interval,
            RetryInterval = options.RetryInterval,
            MaxRetryInterval = options.MaxRetryInterval,
            TimeProvider = options.TimeProvider,
        };
    }

    /// <summary>A watched tag's value changed; after <see cref="Start"/>, every tag is reported once with no old value.</summary>
    public event EventHandler<TagValueChangedEventArgs>? ValueChanged;

    /// <summary>A read failed: the PLC or the link is away. Once per outage; the watch keeps trying.</summary>
    public event EventHandler<ConnectionLostEventArgs>? ConnectionLost;

    /// <summary>A read succeeded again after <see cref="ConnectionLost"/>; the changes since follow.</summary>
    public event EventHandler<ConnectionRestoredEventArgs>? ConnectionRestored;

    /// <summary>A cycle took longer than the interval.</summary>
    public event EventHandler<WatchOverrunEventArgs>? Overrun;

    /// <summary>A handler threw (the watch goes on), or the watch ended because the client was disposed.</summary>
    public event EventHandler<WatchErrorEventArgs>? Error;

    /// <summary>The tags as they were given.</summary>
    public IReadOnlyList<string> Tags => _tagTexts;

    /// <summary>From the start of one cycle to the start of the next.</summary>
    public TimeSpan Interval => _options.Interval;

    /// <summary>Whether a watch is running: between <see cref="Start"/> and <see cref="Stop"/>, unless it ended on its own.</summary>
    public bool IsRunning => _run is { Ended: false };

    /// <summary>
    /// Starts watching, raising the events on the current <see cref="SynchronizationContext"/>. Does nothing while a
    /// watch is running. The tags are checked against the unit's command set here, before anything is read.
    /// </summary>
    /// <exception cref="ArgumentException">A tag cannot be read with the unit's command set (the work area with C-mode).</exception>
    /// <exception cref="ObjectDisposedException">The watcher was disposed.</exception>
    public void Start()
    {
        if (_disposed)
        {
            throw new ObjectDisposedException(nameof(HostLinkWatcher));
        }

        if (IsRunning)
        {
            return;
        }

        var stop = new CancellationTokenSource();
        IAsyncEnumerable<WatchEvent> events;
        try
        {
            events = _unit.WatchAsync(_tags, _options, stop.Token);
        }
        catch
        {
            stop.Dispose();
            throw;
        }

        var run = new Run(this, SynchronizationContext.Current, stop);
        _run = run;
        _ = Task.Run(() => run.LoopAsync(events));
    }

    /// <summary>
    /// Stops watching. Returns at once, waiting for nothing (safe on a UI thread); called on the context's thread, no
    /// event is raised after it returns. Idempotent; <see cref="Start"/> begins a new watch.
    /// </summary>
    public void Stop()
    {
        Run? run = _run;
        _run = null;
        run?.End();
    }

    /// <summary>Stops watching; the watcher cannot be started again. The client is not disposed.</summary>
    public void Dispose()
    {
        _disposed = true;
        Stop();
    }

    private void Raise(WatchEvent e, string tagText)
    {
        switch (e.Kind)
        {
            case WatchEventKind.Changed:
                ValueChanged?.Invoke(this, new TagValueChangedEventArgs(tagText, e.Tag!, e.TagIndex, e.OldValue, e.NewValue, e.Timestamp));
                break;
            case WatchEventKind.Outage:
                ConnectionLost?.Invoke(this, new ConnectionLostEventArgs(e.Exception!, e.Timestamp, e.RetryDelay));
                break;
            case WatchEventKind.Resumed:
                ConnectionRestored?.Invoke(this, new ConnectionRestoredEventArgs(e.Duration, e.Timestamp));
                break;
            case WatchEventKind.Overrun:
                Overrun?.Invoke(this, new WatchOverrunEventArgs(e.Duration, e.Timestamp));
                break;
        }
    }

    /// <summary>Hands <paramref name="exception"/> to <see cref="Error"/>; with no handler, or a handler that throws, throws it where it is.</summary>
    private void Fail(Exception exception, bool watchEnded)
    {
        if (Error is { } handlers)
        {
            try
            {
                handlers(this, new WatchErrorEventArgs(exception, watchEnded));
                return;
            }
            catch (Exception e)
            {
                exception = e;
            }
        }

        ExceptionDispatchInfo.Capture(exception).Throw();
    }

    /// <summary>One watch from Start to Stop: its cancellation, its context, and whether it may still raise events.</summary>
    private sealed class Run(HostLinkWatcher owner, SynchronizationContext? context, CancellationTokenSource stop)
    {
        private volatile bool _ended;

        public bool Ended => _ended;

        public void End()
        {
            _ended = true;
            try
            {
                stop.Cancel();
            }
            catch (ObjectDisposedException)
            {
                // The loop has finished and disposed it.
            }
        }

        public async Task LoopAsync(IAsyncEnumerable<WatchEvent> events)
        {
            try
            {
                await foreach (WatchEvent e in events.ConfigureAwait(false))
                {
                    string tagText = e.Kind == WatchEventKind.Changed ? owner._tagTexts[e.TagIndex] : string.Empty;
                    await OnContextAsync(() => RaiseOrFail(e, tagText)).ConfigureAwait(false);
                }
            }
            catch (OperationCanceledException) when (stop.IsCancellationRequested)
            {
                // Stopped.
            }
            catch (Exception e)
            {
                // The watch cannot go on (the client was disposed under it): said once, on the context.
                await OnContextAsync(() => owner.Fail(e, watchEnded: true)).ConfigureAwait(false);
                _ended = true;
            }
            finally
            {
                stop.Dispose();
            }
        }

        /// <summary>
        /// Runs <paramref name="raise"/> on the context (or here, without one) unless the watch was stopped, and waits
        /// until it has run; a handler's exception goes to <see cref="Fail"/>. Stopping ends the wait, so a context that
        /// no longer pumps (a closed form) cannot hold the loop.
        /// </summary>
        private Task OnContextAsync(Action raise)
        {
            if (context is null)
            {
                Dispatch(raise, onContext: false);
                return Task.CompletedTask;
            }

            var done = new TaskCompletionSource<bool>(TaskCreationOptions.RunContinuationsAsynchronously);
            CancellationTokenRegistration stopped = stop.Token.Register(() => done.TrySetResult(false));
            context.Post(
                _ =>
                {
                    try
                    {
                        Dispatch(raise, onContext: true);
                    }
                    finally
                    {
                        stopped.Dispose();
                        done.TrySetResult(true);
                    }
                },
                null);
            return done.Task;
        }

        private void RaiseOrFail(WatchEvent e, string tagText)
        {
            try
            {
                owner.Raise(e, tagText);
            }
            catch (Exception handlerException)
            {
                owner.Fail(handlerException, watchEnded: false);
            }
        }

        private void Dispatch(Action raise, bool onContext)
        {
            if (_ended)
            {
                return;
            }

            try
            {
                raise();
            }
            catch (Exception unhandled) when (!onContext)
            {
                // No context to throw on: a thread-pool thread, as an unhandled exception of any pool callback.
                ExceptionDispatchInfo captured = ExceptionDispatchInfo.Capture(unhandled);
                ThreadPool.QueueUserWorkItem(_ => captured.Throw());
            }
        }
    }
}
