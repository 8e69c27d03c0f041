using System.Diagnostics;

namespace OmronHostLink.Cli.LineMonitoring;

/// <summary>
/// Wall-clock times for Stopwatch timestamps: one reading of the system clock at start, then the Stopwatch, so that
/// times taken on different threads are ordered and differences are exact to the Stopwatch's resolution.
/// </summary>
internal sealed class MonitorClock
{
    private readonly long _anchorTicks = Stopwatch.GetTimestamp();
    private readonly DateTimeOffset _anchor = DateTimeOffset.UtcNow;

    /// <summary>The wall-clock time of <paramref name="timestamp"/>.</summary>
    public DateTimeOffset At(long timestamp) => _anchor + Stopwatch.GetElapsedTime(_anchorTicks, timestamp);

    /// <summary>From <paramref name="from"/> to <paramref name="to"/>.</summary>
    public static TimeSpan Between(long from, long to) => Stopwatch.GetElapsedTime(from, to);
}
