namespace OmronHostLink.Testing;

/// <summary>
/// Duration texts and the time each is (in ticks), or null where the grammar refuses it: one list for every reader of
/// durations. Each reader's tests read it: the grammar (OmronHostLink.Tests), the DI package's configuration and
/// <c>AddHostLinkClient(..., Action)</c> (OmronHostLink.DependencyInjection.Tests), the console's options
/// (OmronHostLink.Cli.Tests) and the gateway's configuration (OmronHostLink.Gateway.Tests).
/// </summary>
public static class DurationTexts
{
    /// <summary>The grammar's words for a text it refuses, which every reader passes on.</summary>
    public static string Refusal(string text)
        => Duration.TryParse(text, out _, out string? error)
            ? throw new ArgumentException($"'{text}' is a duration; the grammar refuses none of it.", nameof(text))
            : error!;

    /// <summary>Rows of (text, ticks or null), for <c>[MemberData]</c>.</summary>
    public static IEnumerable<object?[]> All =>
    [
        ["500ms", (long?)(TimeSpan.FromMilliseconds(500).Ticks)],
        ["2s", (long?)(TimeSpan.FromSeconds(2).Ticks)],
        ["1.5min", (long?)(TimeSpan.FromSeconds(90).Ticks)],
        ["1.5m", (long?)(TimeSpan.FromSeconds(90).Ticks)],
        ["0.05h", (long?)(TimeSpan.FromMinutes(3).Ticks)],
        ["00:00:02", (long?)(TimeSpan.FromSeconds(2).Ticks)],
        ["00:00:00.250", (long?)(TimeSpan.FromMilliseconds(250).Ticks)],
        [" 250 ms ", (long?)(TimeSpan.FromMilliseconds(250).Ticks)],
        ["1.5S", (long?)(TimeSpan.FromMilliseconds(1500).Ticks)],
        ["0.0001ms", (long?)(1)],
        ["300", (long?)(null)],
        ["0.5", (long?)(null)],
        ["abc", (long?)(null)],
        ["5x", (long?)(null)],
        ["-1s", (long?)(null)],
        ["-00:00:01", (long?)(null)],
        ["00:00:xx", (long?)(null)],
        ["1.5 fortnights", (long?)(null)],
    ];
}
