namespace OmronHostLink.Gateway.Outputs;

/// <summary>The state of one PLC unit on a link, as the polling sees it.</summary>
public enum UnitState
{
    /// <summary>The unit answers.</summary>
    Online,

    /// <summary>The unit does not answer (timeout, lost connection, damaged answers); one of its groups keeps trying.</summary>
    CommError,

    /// <summary>
    /// The unit stayed silent for the link's <c>Demotion:After</c> polls in a row: it is not polled for
    /// <c>Demotion:Period</c>, then one presence probe decides whether it is back.
    /// </summary>
    Demoted,
}
