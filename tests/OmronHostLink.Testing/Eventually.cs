namespace OmronHostLink.Testing;

/// <summary>
/// The tests' one wait for a condition: awaited, never slept. A condition about a log is looked at again whenever the
/// log gains an entry; any other is looked at on a short periodic tick. Fails after <see cref="Patience"/> (or the
/// given patience), saying what was awaited and, when given, what was seen.
/// </summary>
public static class Eventually
{
    /// <summary>The one default: long enough that a loaded two-core machine never fails a test that is not about time.</summary>
    public static readonly TimeSpan Patience = TimeSpan.FromSeconds(30);

    private static readonly TimeSpan Tick = TimeSpan.FromMilliseconds(5);

    /// <summary>Waits until <paramref name="condition"/> holds.</summary>
    /// <param name="condition">What must come true.</param>
    /// <param name="what">What is awaited, for the failure: "the link polls".</param>
    /// <param name="seen">What was seen, for the failure (a log dump), or null.</param>
    /// <param name="patience">How long at most; default <see cref="Patience"/>.</param>
    public static async Task UntilAsync(Func<bool> condition, string what = "the condition holds", Func<string>? seen = null, TimeSpan? patience = null)
    {
        using var timeout = new CancellationTokenSource(patience ?? Patience);
        using var tick = new PeriodicTimer(Tick);
        while (!condition())
        {
            try
            {
                await tick.WaitForNextTickAsync(timeout.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (timeout.IsCancellationRequested)
            {
                if (condition())
                {
                    return;
                }

                throw new TimeoutException($"Timed out after {(patience ?? Patience).TotalSeconds:0.#} s waiting until {what}." + (seen is null ? "" : Environment.NewLine + seen()));
            }
        }
    }

    /// <summary>Waits until <paramref name="condition"/> (about what <paramref name="logs"/> captured) holds, looking again at each new entry.</summary>
    public static async Task UntilAsync(Func<bool> condition, string what, CapturingLoggerProvider logs, TimeSpan? patience = null)
    {
        ArgumentNullException.ThrowIfNull(logs);
        using var timeout = new CancellationTokenSource(patience ?? Patience);
        while (true)
        {
            Task next = logs.NextEntry;
            if (condition())
            {
                return;
            }

            try
            {
                await next.WaitAsync(timeout.Token).ConfigureAwait(false);
            }
            catch (OperationCanceledException) when (timeout.IsCancellationRequested)
            {
                if (condition())
                {
                    return;
                }

                throw new TimeoutException($"Timed out after {(patience ?? Patience).TotalSeconds:0.#} s waiting until {what}. Log:{Environment.NewLine}{logs.Dump()}");
            }
        }
    }
}
