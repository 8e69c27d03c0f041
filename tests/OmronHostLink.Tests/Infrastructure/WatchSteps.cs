namespace OmronHostLink.Tests.Infrastructure;

/// <summary>
/// A watch's events taken one at a time. The wait for each only bounds a hang: it is long enough for the demotion
/// tests, whose silent units cost their real turnaround allowance, on a loaded machine.
/// </summary>
internal static class WatchSteps
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(30);

    /// <summary>The watch's next event.</summary>
    public static async Task<WatchEvent> Next(IAsyncEnumerator<WatchEvent> watch)
        => await Completed(watch.MoveNextAsync(), watch);

    /// <summary>The event that <paramref name="pending"/>, a <c>MoveNextAsync</c> of <paramref name="watch"/>, brings.</summary>
    public static async Task<WatchEvent> Completed(ValueTask<bool> pending, IAsyncEnumerator<WatchEvent> watch)
    {
        bool more = await pending.AsTask().WaitAsync(Patience);
        more.Should().BeTrue("a watch never ends by itself");
        return watch.Current;
    }
}
