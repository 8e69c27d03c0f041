namespace OmronHostLink.Gateway.Status;

/// <summary>
/// Transactions per second of each link, from its running count: the count is sampled when a page asks (nothing runs
/// while no page is open), and the rate is taken over the last few seconds of samples.
/// </summary>
/// <param name="time">The clock of the samples.</param>
internal sealed class TransactionRates(TimeProvider time)
{
    /// <summary>The span a rate is taken over.</summary>
    public static readonly TimeSpan Window = TimeSpan.FromSeconds(5);

    /// <summary>Samples closer together than this are not kept (several pages asking at once).</summary>
    private static readonly TimeSpan Spacing = TimeSpan.FromMilliseconds(200);

    private readonly Dictionary<string, Queue<(long At, long Count)>> _samples = new(StringComparer.Ordinal);

    /// <summary>Takes <paramref name="count"/> as the link's count now; the rate per second over the window, null until two samples are a spacing apart.</summary>
    public double? Sample(string link, long count)
    {
        long now = time.GetTimestamp();
        lock (_samples)
        {
            if (!_samples.TryGetValue(link, out Queue<(long At, long Count)>? samples))
            {
                samples = new Queue<(long, long)>();
                _samples.Add(link, samples);
            }

            if (samples.Count == 0 || time.GetElapsedTime(samples.Last().At, now) >= Spacing)
            {
                samples.Enqueue((now, count));
            }

            // Keep one sample older than the window, so the rate always spans it once the page has been open that long.
            while (samples.Count > 2 && time.GetElapsedTime(samples.ElementAt(1).At, now) >= Window)
            {
                samples.Dequeue();
            }

            (long firstAt, long firstCount) = samples.Peek();
            TimeSpan span = time.GetElapsedTime(firstAt, now);
            return samples.Count < 2 || span < Spacing ? null : Math.Max(0, count - firstCount) / span.TotalSeconds;
        }
    }
}
