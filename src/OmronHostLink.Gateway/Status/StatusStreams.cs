using System.Net.ServerSentEvents;
using System.Runtime.CompilerServices;
using System.Text.Json;

namespace OmronHostLink.Gateway.Status;

/// <summary>
/// What an open page is sent, as server-sent events: the Lines and Outputs views every refresh interval, the Tags view
/// whole once and then only the tags that changed, a link's trace the frames after the page's last. Each stream ends
/// when the page goes or the page's application stops; a page that is not open costs nothing.
/// </summary>
/// <param name="options">The <c>Status</c> section (the refresh interval).</param>
/// <param name="lines">The Lines view.</param>
/// <param name="tags">The Tags view's store.</param>
/// <param name="outputs">The Outputs view.</param>
/// <param name="traces">The line traces.</param>
/// <param name="time">The clock of the refresh interval.</param>
/// <param name="stopping">Cancelled when the page's application stops.</param>
internal sealed class StatusStreams(StatusOptions options, LinesView lines, TagBoard tags, OutputsView outputs, LineTraces traces, TimeProvider time, CancellationToken stopping)
{
    /// <summary>A Tags update is sent at least this often, changes or not, so that a page sees the gateway is there.</summary>
    private static readonly TimeSpan Heartbeat = TimeSpan.FromSeconds(10);

    private TimeSpan Refresh => options.RefreshInterval;

    /// <summary>The Lines view, now and every refresh interval.</summary>
    public async IAsyncEnumerable<SseItem<string>> Lines([EnumeratorCancellation] CancellationToken cancellationToken)
    {
        using CancellationTokenSource until = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, stopping);
        using var timer = new PeriodicTimer(Refresh, time);
        do
        {
            yield return new SseItem<string>(JsonSerializer.Serialize(lines.Snapshot(), StatusJsonContext.Default.LinesDocument), "lines");
        }
        while (await Tick(timer, until.Token).ConfigureAwait(false));
    }

    /// <summary>The Outputs view, now and every refresh interval.</summary>
    public async IAsyncEnumerable<SseItem<string>> Outputs([EnumeratorCancellation] CancellationToken cancellationToken)
    {
        using CancellationTokenSource until = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, stopping);
        using var timer = new PeriodicTimer(Refresh, time);
        do
        {
            yield return new SseItem<string>(JsonSerializer.Serialize(outputs.Snapshot(), StatusJsonContext.Default.OutputsDocument), "outputs");
        }
        while (await Tick(timer, until.Token).ConfigureAwait(false));
    }

    /// <summary>Every tag (<c>snapshot</c>), then each refresh interval the tags that changed (<c>changes</c>).</summary>
    public async IAsyncEnumerable<SseItem<string>> Tags([EnumeratorCancellation] CancellationToken cancellationToken)
    {
        // The version first: what changes while the snapshot is taken is sent again with the next changes.
        using CancellationTokenSource until = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, stopping);
        long version = tags.Version;
        yield return new SseItem<string>(Serialize(tags.All()), "snapshot");
        using var timer = new PeriodicTimer(Refresh, time);
        long lastSent = time.GetTimestamp();
        while (await Tick(timer, until.Token).ConfigureAwait(false))
        {
            long now = tags.Version;
            if (now == version && time.GetElapsedTime(lastSent) < Heartbeat)
            {
                continue;
            }

            List<TagRow> changed = tags.ChangedSince(version);
            version = now;
            lastSent = time.GetTimestamp();
            yield return new SseItem<string>(Serialize(changed), "changes");
        }
    }

    /// <summary>
    /// The frames of <paramref name="link"/>'s trace after number <paramref name="after"/>, then each refresh interval
    /// the new ones; the link's frames are taken while this runs.
    /// </summary>
    public async IAsyncEnumerable<SseItem<string>> Trace(string link, long after, [EnumeratorCancellation] CancellationToken cancellationToken)
    {
        LineTrace trace = traces.Trace(link) ?? throw new ArgumentException($"No link {link}.", nameof(link));
        using CancellationTokenSource until = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, stopping);
        using IDisposable? watching = traces.Watch(link);
        using var timer = new PeriodicTimer(Refresh, time);
        yield return new SseItem<string>(link, "tracing");
        do
        {
            (List<TracedFrame> frames, long lost) = trace.After(after);
            if (frames.Count > 0 || lost > 0)
            {
                after = frames.Count > 0 ? frames[^1].Seq : after + lost;
                yield return new SseItem<string>(JsonSerializer.Serialize(Document(link, frames, lost), StatusJsonContext.Default.TraceDocument), "frames");
            }
        }
        while (await Tick(timer, until.Token).ConfigureAwait(false));
    }

    /// <summary>The frames of a link's trace after number <paramref name="after"/>, without taking any.</summary>
    public static TraceDocument Document(string link, IReadOnlyList<TracedFrame> frames, long lost)
        => new() { Link = link, Lost = lost, Frames = frames.Select(f => f.View).ToList() };

    private string Serialize(List<TagRow> rows)
        => JsonSerializer.Serialize(new TagsDocument { Now = time.GetUtcNow(), Tags = rows }, StatusJsonContext.Default.TagsDocument);

    /// <summary>Waits for the next tick; false when the page went or the gateway stops.</summary>
    private static async ValueTask<bool> Tick(PeriodicTimer timer, CancellationToken cancellationToken)
    {
        try
        {
            return await timer.WaitForNextTickAsync(cancellationToken).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
            return false;
        }
    }
}
