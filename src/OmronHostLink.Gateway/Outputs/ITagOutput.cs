namespace OmronHostLink.Gateway.Outputs;

/// <summary>
/// Where the polling engine hands what it learns: each tag's outcome, each link's state, and the client a link polls
/// with (so that writes share the link's one owner of the wire). Implementations return at once: polling never waits
/// for an output.
/// </summary>
public interface ITagOutput
{
    /// <summary>A link starts polling through <paramref name="client"/>; its state is online until told otherwise.</summary>
    /// <param name="link">The link's configured name.</param>
    /// <param name="client">The link's client; writes for the link's tags go through it.</param>
    void LinkOpened(string link, HostLinkUnit client);

    /// <summary>A link's state changed. <see cref="LinkState.Offline"/> also means its client is closed.</summary>
    /// <param name="link">The link's configured name.</param>
    /// <param name="state">The new state.</param>
    /// <param name="detail">Why, for a state other than online; null otherwise.</param>
    void LinkChanged(string link, LinkState state, string? detail = null);

    /// <summary>The outcome of reading a tag: a value (<see cref="TagQuality.Good"/>) or why it could not be read.</summary>
    /// <param name="change">The outcome. The sink decides whether it is a change worth passing on.</param>
    void TagChanged(TagChange change);

    /// <summary>
    /// A PLC unit's state changed: it stopped answering, was demoted, or answers again (<see cref="UnitState.Online"/>;
    /// every unit starts online with its link). Its tags' outcomes come through <see cref="TagChanged"/> as well.
    /// </summary>
    /// <param name="link">The link's configured name.</param>
    /// <param name="unit">The unit number, 0–31.</param>
    /// <param name="state">The new state.</param>
    /// <param name="detail">Why, for a state other than online; null otherwise.</param>
    void UnitChanged(string link, int unit, UnitState state, string? detail = null)
    {
    }

    /// <summary>A scan class was planned: at start, and again when its plan changes (a unit's model learnt, QQ refused).</summary>
    /// <param name="plan">The reads it makes each cycle.</param>
    void ScanPlanned(ScanPlan plan)
    {
    }

    /// <summary>A scan class read every tag once more.</summary>
    /// <param name="cycle">The cycle's time.</param>
    void ScanCycled(ScanCycle cycle)
    {
    }
}
