using System.Globalization;
using OmronHostLink.Planning;

namespace OmronHostLink;

/// <summary>
/// One event of a watch (<see cref="HostLinkUnit.WatchAsync(IReadOnlyList{PlcTag}, WatchOptions, CancellationToken)"/>):
/// a changed value, the start or end of an outage, or an overrun cycle. Immutable; the factories let a test double of
/// <see cref="IHostLinkUnit"/> produce the same events as a real watch.
/// </summary>
public sealed class WatchEvent
{
    private static readonly ushort[] NoWords = [];

    private WatchEvent(WatchEventKind kind, DateTimeOffset timestamp, int tagIndex = -1, PlcTag? tag = null, PlcValue? oldValue = null, PlcValue newValue = default, Exception? exception = null, TimeSpan duration = default, TimeSpan retryDelay = default, IReadOnlyList<ushort>? words = null, ReadPlan? plan = null)
    {
        Plan = plan;
        RetryDelay = retryDelay;
        Words = words ?? NoWords;
        Kind = kind;
        Timestamp = timestamp;
        TagIndex = tagIndex;
        Tag = tag;
        OldValue = oldValue;
        NewValue = newValue;
        Exception = exception;
        Duration = duration;
    }

    /// <summary>What the event reports.</summary>
    public WatchEventKind Kind { get; }

    /// <summary>
    /// When: for <see cref="WatchEventKind.Changed"/> the time the cycle's read completed (the value was read by then);
    /// for the others the time the watch noticed. From the watch's <see cref="WatchOptions.TimeProvider"/>.
    /// </summary>
    public DateTimeOffset Timestamp { get; }

    /// <summary>The changed tag's position in the watched list; -1 for events that are not about a tag.</summary>
    public int TagIndex { get; }

    /// <summary>The changed tag; null for events that are not about a tag.</summary>
    public PlcTag? Tag { get; }

    /// <summary>The value reported before for the tag; null on the first report of the tag (<see cref="IsInitial"/>) and for other kinds.</summary>
    public PlcValue? OldValue { get; }

    /// <summary>The tag's new value, decoded as its <see cref="PlcTag.Type"/>; <c>default</c> for events that are not about a tag.</summary>
    public PlcValue NewValue { get; }

    /// <summary>
    /// For <see cref="WatchEventKind.Changed"/>: the words <see cref="NewValue"/> was decoded from, as read (one, two or
    /// four; for a bit, the word that holds it; for a completion flag, one word 0 or 1), so a subscriber can show or
    /// publish them raw. Empty for other kinds, and for a change made by <see cref="Changed"/> without words.
    /// </summary>
    public IReadOnlyList<ushort> Words { get; }

    /// <summary>
    /// For <see cref="WatchEventKind.Outage"/>, <see cref="WatchEventKind.RetryFailed"/> and
    /// <see cref="WatchEventKind.Demoted"/>: why the cycle (or the probe) failed (see
    /// <see cref="HostLinkException.IsTransient"/>). Null otherwise.
    /// </summary>
    public Exception? Exception { get; }

    /// <summary>
    /// For <see cref="WatchEventKind.Overrun"/>: how long the cycle took; for <see cref="WatchEventKind.Polled"/>: how
    /// long its read took; for <see cref="WatchEventKind.Resumed"/>: how long the outage lasted. Zero otherwise.
    /// </summary>
    public TimeSpan Duration { get; }

    /// <summary>
    /// For <see cref="WatchEventKind.Outage"/> and <see cref="WatchEventKind.RetryFailed"/>: how long the watch waits
    /// before its next try (see <see cref="WatchOptions.MaxRetryInterval"/>); for <see cref="WatchEventKind.Demoted"/>:
    /// the demotion period before the next probe. Zero otherwise.
    /// </summary>
    public TimeSpan RetryDelay { get; }

    /// <summary>For <see cref="WatchEventKind.Planned"/>: the plan the watch reads with from this cycle on. Null otherwise.</summary>
    public ReadPlan? Plan { get; }

    /// <summary>Whether this is the first report of a tag's value (a change with no old value).</summary>
    public bool IsInitial => Kind == WatchEventKind.Changed && OldValue is null;

    /// <summary>A change of a tag's value (or its first report, with <paramref name="oldValue"/> null).</summary>
    /// <param name="tagIndex">The tag's position in the watched list.</param>
    /// <param name="tag">The tag.</param>
    /// <param name="oldValue">The value reported before, or null for the first report.</param>
    /// <param name="newValue">The value read.</param>
    /// <param name="timestamp">When the read completed.</param>
    /// <param name="words">The words the value was decoded from (<see cref="Words"/>); null for none.</param>
    /// <returns>The event.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="tag"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="tagIndex"/> is negative.</exception>
    public static WatchEvent Changed(int tagIndex, PlcTag tag, PlcValue? oldValue, PlcValue newValue, DateTimeOffset timestamp, IReadOnlyList<ushort>? words = null)
    {
        Guard.NotNull(tag);
        if (tagIndex < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(tagIndex), tagIndex, "A tag index cannot be negative.");
        }

        return new(WatchEventKind.Changed, timestamp, tagIndex, tag, oldValue, newValue, words: words);
    }

    /// <summary>The start of an outage: a cycle failed with <paramref name="exception"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="exception"/> is null.</exception>
    public static WatchEvent Outage(Exception exception, DateTimeOffset timestamp)
        => new(WatchEventKind.Outage, timestamp, exception: Guard.NotNull(exception));

    /// <summary>The start of an outage: a cycle failed with <paramref name="exception"/>; the next try is in <paramref name="retryDelay"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="exception"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="retryDelay"/> is negative.</exception>
    public static WatchEvent Outage(Exception exception, DateTimeOffset timestamp, TimeSpan retryDelay)
        => new(WatchEventKind.Outage, timestamp, exception: Guard.NotNull(exception), retryDelay: NotNegative(retryDelay, nameof(retryDelay)));

    /// <summary>Another failed try during an outage, with <paramref name="exception"/>; the next try is in <paramref name="retryDelay"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="exception"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="retryDelay"/> is negative.</exception>
    public static WatchEvent RetryFailed(Exception exception, DateTimeOffset timestamp, TimeSpan retryDelay)
        => new(WatchEventKind.RetryFailed, timestamp, exception: Guard.NotNull(exception), retryDelay: NotNegative(retryDelay, nameof(retryDelay)));

    /// <summary>The unit is demoted after a cycle failed with <paramref name="exception"/>; the next probe is in <paramref name="period"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="exception"/> is null.</exception>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="period"/> is negative.</exception>
    public static WatchEvent Demoted(Exception exception, DateTimeOffset timestamp, TimeSpan period)
        => new(WatchEventKind.Demoted, timestamp, exception: Guard.NotNull(exception), retryDelay: NotNegative(period, nameof(period)));

    /// <summary>A successful cycle whose read took <paramref name="readTime"/>.</summary>
    public static WatchEvent Polled(TimeSpan readTime, DateTimeOffset timestamp)
        => new(WatchEventKind.Polled, timestamp, duration: readTime);

    /// <summary>The end of an outage that lasted <paramref name="outage"/>.</summary>
    public static WatchEvent Resumed(TimeSpan outage, DateTimeOffset timestamp)
        => new(WatchEventKind.Resumed, timestamp, duration: outage);

    /// <summary>A cycle that took <paramref name="cycleTime"/>, longer than the interval.</summary>
    public static WatchEvent Overrun(TimeSpan cycleTime, DateTimeOffset timestamp)
        => new(WatchEventKind.Overrun, timestamp, duration: cycleTime);

    /// <summary>The reads a watch makes each cycle from now on: <paramref name="plan"/>.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="plan"/> is null.</exception>
    public static WatchEvent Planned(ReadPlan plan, DateTimeOffset timestamp)
        => new(WatchEventKind.Planned, timestamp, plan: Guard.NotNull(plan));

    /// <summary>
    /// One line for logs: <c>D100 (Float): 1.5 → 2.5</c>, <c>outage: …</c>, <c>resumed after 3 s</c>, <c>overrun: cycle
    /// took 1.2 s</c>, <c>polled in 0.012 s</c>, <c>still failing: …; next try in 4 s</c>.
    /// </summary>
    public override string ToString()
    {
        string at = Timestamp.ToString("O", CultureInfo.InvariantCulture);
        return Kind switch
        {
            WatchEventKind.Changed => OldValue is { } old ? $"{at} {Tag}: {old} → {NewValue}" : $"{at} {Tag}: {NewValue}",
            WatchEventKind.Outage => $"{at} outage: {Exception!.Message}",
            WatchEventKind.Resumed => $"{at} resumed after {Seconds(Duration)} s",
            WatchEventKind.Polled => $"{at} polled in {Seconds(Duration)} s",
            WatchEventKind.RetryFailed => $"{at} still failing: {Exception!.Message}; next try in {Seconds(RetryDelay)} s",
            WatchEventKind.Demoted => $"{at} demoted: {Exception!.Message}; next probe in {Seconds(RetryDelay)} s",
            WatchEventKind.Planned => $"{at} planned: {Plan}",
            _ => $"{at} overrun: cycle took {Seconds(Duration)} s",
        };
    }

    private static string Seconds(TimeSpan time) => time.TotalSeconds.ToString("0.###", CultureInfo.InvariantCulture);

    private static TimeSpan NotNegative(TimeSpan value, string name)
        => value >= TimeSpan.Zero ? value : throw new ArgumentOutOfRangeException(name, value, "A delay cannot be negative.");
}
