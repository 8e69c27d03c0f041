using System.Collections.Concurrent;
using Microsoft.Extensions.Logging;

namespace OmronHostLink.Testing;

/// <summary>One captured log entry, with its structured fields.</summary>
public sealed record LogEntry(DateTimeOffset Time, string Category, LogLevel Level, EventId EventId, string Message, IReadOnlyDictionary<string, object?> Fields)
{
    public object? this[string field] => Fields.TryGetValue(field, out object? v) ? v : null;
}

/// <summary>An in-memory logger provider for host tests.</summary>
public sealed class CapturingLoggerProvider : ILoggerProvider
{
    private readonly ConcurrentQueue<LogEntry> _entries = new();
    private TaskCompletionSource _next = new(TaskCreationOptions.RunContinuationsAsynchronously);

    /// <summary>Completes when the next entry is logged.</summary>
    public Task NextEntry => Volatile.Read(ref _next).Task;

    public IReadOnlyList<LogEntry> Entries => _entries.ToArray();

    public IReadOnlyList<LogEntry> WithEvent(int eventId) => _entries.Where(e => e.EventId.Id == eventId).ToArray();

    public ILogger CreateLogger(string categoryName) => new Logger(this, categoryName);

    public void Dispose()
    {
    }

    public string Dump() => string.Join(Environment.NewLine, _entries.Select(e => $"{e.Time:HH:mm:ss.fff} {e.Level} [{e.EventId.Id}] {e.Category}: {e.Message}"));

    private sealed class Logger(CapturingLoggerProvider owner, string category) : ILogger
    {
        public IDisposable? BeginScope<TState>(TState state)
            where TState : notnull => null;

        public bool IsEnabled(LogLevel logLevel) => logLevel != LogLevel.None;

        public void Log<TState>(LogLevel logLevel, EventId eventId, TState state, Exception? exception, Func<TState, Exception?, string> formatter)
        {
            var fields = new Dictionary<string, object?>();
            if (state is IEnumerable<KeyValuePair<string, object?>> pairs)
            {
                foreach (KeyValuePair<string, object?> pair in pairs)
                {
                    fields[pair.Key] = pair.Value;
                }
            }

            owner._entries.Enqueue(new LogEntry(DateTimeOffset.Now, category, logLevel, eventId, formatter(state, exception), fields));
            Interlocked.Exchange(ref owner._next, new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously)).TrySetResult();
        }
    }
}
