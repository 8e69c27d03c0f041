namespace OmronHostLink;

/// <summary>
/// An exception thrown by one of a watcher's event handlers (the watch goes on), or the end of a watch that could not
/// go on (<see cref="WatchEnded"/>: the client was disposed under it).
/// </summary>
public sealed class WatchErrorEventArgs : EventArgs
{
    /// <summary>Creates the event's data.</summary>
    /// <param name="exception">The exception.</param>
    /// <param name="watchEnded">Whether the watch has ended because of it.</param>
    public WatchErrorEventArgs(Exception exception, bool watchEnded)
    {
        Exception = Guard.NotNull(exception);
        WatchEnded = watchEnded;
    }

    /// <summary>The exception a handler threw, or the one that ended the watch.</summary>
    public Exception Exception { get; }

    /// <summary>
    /// False for a handler's exception: the watch goes on with the next event. True when the watch itself has ended
    /// (the client was disposed while watching); <c>Start</c> begins a new one.
    /// </summary>
    public bool WatchEnded { get; }
}
