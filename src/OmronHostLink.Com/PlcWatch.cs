using OmronHostLink.Planning;

namespace OmronHostLink.Com;

/// <summary>
/// One watch of a <see cref="Plc"/>: the library's polling engine (<see cref="IHostLinkUnit.WatchAsync(IReadOnlyList{PlcTag}, WatchOptions, CancellationToken)"/>)
/// on a thread-pool thread, each tag's latest value and the tags changed since a caller last asked, and the events,
/// raised on the thread that started the watch.
/// </summary>
/// <remarks>
/// <para>
/// Values are recorded on the pool thread as they arrive, so <see cref="WaitForChanges"/> and <see cref="LatestValue"/>
/// need no message loop. Events are raised only while a COM client is connected to them. On a single-threaded
/// apartment (a VB6 form, VBA, a script) they are posted to a message window of that thread and run when it
/// dispatches messages; the watch waits for each handler to finish before it goes on, so a slow handler slows the
/// polling instead of queueing events. In the multithreaded apartment there is no thread to return to, and they are
/// raised on the pool thread.
/// </para>
/// <para>
/// A handler that fails has already been reported by its own language (VBScript's host, VB's error dialog); the failure
/// it returns to the event's raiser is not the watch's and does not stop it.
/// </para>
/// </remarks>
internal sealed class PlcWatch
{
    private readonly IHostLinkUnit _unit;
    private readonly string[] _texts;
    private readonly PlcTag[] _tags;
    private readonly WatchOptions _options;
    private readonly Plc _owner;
    private readonly object _gate = new();
    private readonly Dictionary<string, object> _latest = new(StringComparer.OrdinalIgnoreCase);
    private readonly List<string> _changed = [];
    private readonly ManualResetEventSlim _changes = new(false);
    private readonly CancellationTokenSource _stop = new();
    private MessageWindowContext? _window;
    private volatile bool _running;
    private volatile string _error = "";

    /// <exception cref="FormatException">A tag is not valid.</exception>
    public PlcWatch(IHostLinkUnit unit, string[] tags, TimeSpan interval, Plc owner)
    {
        _unit = unit;
        _texts = tags;
        _tags = tags.Select(t => PlcTag.Parse(t)).ToArray();
        _options = new WatchOptions { Interval = interval };
        _options.Validate();
        _owner = owner;
    }

    public bool IsRunning => _running;

    /// <summary>Why the watch cannot read, while it cannot.</summary>
    public string Error => _error;

    /// <summary>Starts polling; events will come back to this thread when it is single-threaded.</summary>
    /// <exception cref="ArgumentException">A tag cannot be read with the unit's command set (nothing is read).</exception>
    public void Start()
    {
        IAsyncEnumerable<WatchEvent> events = _unit.WatchAsync(_tags, _options, _stop.Token);
        if (Thread.CurrentThread.GetApartmentState() == ApartmentState.STA)
        {
            _window = new MessageWindowContext();
        }

        _running = true;
        _ = Task.Run(() => LoopAsync(events));
    }

    /// <summary>Stops polling; called on the watch's thread, no event is raised after it returns.</summary>
    public void Stop()
    {
        _running = false;
        _stop.Cancel();
        _window?.Dispose();
        _window = null;
        _changes.Set();
    }

    public object LatestValue(string tag)
    {
        lock (_gate)
        {
            if (_latest.TryGetValue(tag, out object? value))
            {
                return value;
            }
        }

        if (!_texts.Contains(tag, StringComparer.OrdinalIgnoreCase))
        {
            throw PlcErrors.Raise(PlcErrors.InvalidArgument, $"'{tag}' is not watched; the watch has {string.Join(", ", _texts)}.");
        }

        return null!; // Empty: not read yet
    }

    /// <summary>The tags changed since the last call, waiting up to <paramref name="timeout"/> for one.</summary>
    public object WaitForChanges(TimeSpan timeout)
    {
        _changes.Wait(timeout);
        lock (_gate)
        {
            object[] changed = _changed.ToArray<object>();
            _changed.Clear();
            if (_running)
            {
                _changes.Reset();
            }

            return changed;
        }
    }

    private async Task LoopAsync(IAsyncEnumerable<WatchEvent> events)
    {
        try
        {
            await foreach (WatchEvent e in events.ConfigureAwait(false))
            {
                Action? raise = Record(e);
                if (raise is not null && _owner.HasEventSinks)
                {
                    await RaiseAsync(raise).ConfigureAwait(false);
                }
            }
        }
        catch (OperationCanceledException) when (_stop.IsCancellationRequested)
        {
            // Stopped.
        }
        catch (Exception e)
        {
            // The watch cannot go on (the link was closed under it).
            _error = e.Message;
        }
        finally
        {
            _running = false;
            _changes.Set();
        }
    }

    /// <summary>Records the event's value or outage and returns how to raise it, or null for events that raise nothing.</summary>
    private Action? Record(WatchEvent e)
    {
        switch (e.Kind)
        {
            case WatchEventKind.Changed:
                string tag = _texts[e.TagIndex];
                object value = ComValues.From(e.NewValue.ToObject());
                lock (_gate)
                {
                    _latest[tag] = value;
                    if (!_changed.Contains(tag, StringComparer.OrdinalIgnoreCase))
                    {
                        _changed.Add(tag);
                    }

                    _changes.Set();
                }

                return () => _owner.RaiseValueChanged(tag, value);
            case WatchEventKind.Outage:
                Exception failure = e.Exception!;
                _error = failure.Message;
                return () => _owner.RaiseConnectionLost(PlcErrors.HResultOf(failure), failure.Message);
            case WatchEventKind.Resumed:
                _error = "";
                double seconds = e.Duration.TotalSeconds;
                return () => _owner.RaiseConnectionRestored(seconds);
            default:
                return null;
        }
    }

    /// <summary>Raises on the watch's thread and waits until the handler has run, or until the watch stops.</summary>
    private Task RaiseAsync(Action raise)
    {
        MessageWindowContext? window = _window;
        if (window is null)
        {
            Invoke(raise);
            return Task.CompletedTask;
        }

        var done = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        CancellationTokenRegistration stopped = _stop.Token.Register(() => done.TrySetResult());
        window.Post(
            _ =>
            {
                try
                {
                    if (_running)
                    {
                        Invoke(raise);
                    }
                }
                finally
                {
                    stopped.Dispose();
                    done.TrySetResult();
                }
            },
            null);
        return done.Task;
    }

    private static void Invoke(Action raise)
    {
        try
        {
            raise();
        }
        catch (Exception e) when (e is System.Runtime.InteropServices.COMException or System.Reflection.TargetInvocationException)
        {
            // The handler's own failure, reported by its language already (see the remarks).
        }
    }
}
