namespace OmronHostLink.Gateway.Configuration;

/// <summary>
/// The <c>HostLink:Links:NAME:Demotion</c> section: a PLC unit that stays silent is demoted, so that the other units on
/// a multidrop line keep their poll rate (the watch's <see cref="WatchOptions.DemoteAfter"/> and
/// <see cref="WatchOptions.DemotionPeriod"/>).
/// </summary>
internal sealed class DemotionOptions
{
    /// <summary>
    /// After how many polls in a row the unit did not answer (each with the link's read retries) it is demoted: its
    /// tags are comm-error, it is not polled for <see cref="Period"/>, then one presence probe (one TS, no retry) decides
    /// whether it is polled again. 0 never demotes (the unit is retried with the link's backoff instead). Default 3.
    /// </summary>
    public int After { get; set; } = 3;

    /// <summary>How long a demoted unit is left alone before the next probe. Default 10 s.</summary>
    public TimeSpan Period { get; set; } = TimeSpan.FromSeconds(10);

    /// <summary>Adds the problems of <paramref name="demotion"/> (at <paramref name="path"/>, the link's key) to <paramref name="failures"/>.</summary>
    internal static void Validate(string path, DemotionOptions? demotion, List<string> failures)
    {
        if (demotion is null)
        {
            failures.Add($"{path}:Demotion is missing.");
            return;
        }

        if (demotion.After is < 0 or > WatchOptions.MaxDemoteAfter)
        {
            failures.Add($"{path}:Demotion:After must be 0 (never demote) to {WatchOptions.MaxDemoteAfter} polls; it is {demotion.After}.");
        }

        if (demotion.Period <= TimeSpan.Zero || demotion.Period > TimeSpan.FromDays(1))
        {
            failures.Add($"{path}:Demotion:Period must be more than 0 and at most 1 day; it is {demotion.Period}.");
        }
    }
}
