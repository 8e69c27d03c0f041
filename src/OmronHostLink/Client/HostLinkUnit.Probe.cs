namespace OmronHostLink;

/// <summary>Is anyone there: a presence probe for scanning a multidrop line.</summary>
public partial class HostLinkUnit
{
    /// <summary>
    /// Probes whether this unit answers: one TS (TEST) with a fresh random token, never retried, waiting only the
    /// frame's wire time plus <paramref name="turnaround"/> (default: the client's
    /// <see cref="HostLinkClientOptions.TurnaroundAllowance"/>). Unlike <see cref="TestAsync"/>, a unit that stays
    /// silent costs that one deadline and no resynchronisation exchange, so probing 32 unit numbers of a line takes
    /// 32 short deadlines at most; the link stays able to tell any late answer from the next one.
    /// </summary>
    /// <param name="turnaround">How long the unit may take to start answering; more than 0 and at most 1 minute.</param>
    /// <param name="cancellationToken">Cancels the probe.</param>
    /// <returns>The round-trip time, or null when the unit did not answer in time.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The turnaround is not more than 0 and at most 1 minute.</exception>
    /// <exception cref="HostLinkConnectionException">The port or connection cannot be opened, or was lost.</exception>
    public Task<TimeSpan?> ProbeAsync(TimeSpan? turnaround = null, CancellationToken cancellationToken = default)
    {
        TimeSpan wait = turnaround ?? Options.TurnaroundAllowance;
        if (SettingRules.TurnaroundAllowance(wait) is { } problem)
        {
            throw new ArgumentOutOfRangeException(nameof(turnaround), wait, $"The turnaround {problem}.");
        }

        return Connection.ProbeAsync(UnitNumber, wait, cancellationToken).AsTask();
    }

    /// <summary>How long this unit may take to start answering (the client's setting), for messages about its silence.</summary>
    internal TimeSpan TurnaroundAllowance => Options.TurnaroundAllowance;
}
